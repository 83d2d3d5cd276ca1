// What the CPU offers beyond the build's baseline (SSE2 on x86-64). A kernel with a wider path
// picks it at run time, so one binary runs on every machine, and the paths give the same bits.
#pragma once

#if defined(__x86_64__) || defined(__i386__)
#define S4D_X86 1
// A function compiled for AVX (call it only when kHasAvx): the AVX helpers inline into it.
#define S4D_AVX_TARGET __attribute__((target("avx")))
#else
#define S4D_AVX_TARGET
#endif

namespace s4d::cpu {

// AVX (256-bit registers; not FMA, so products round as in SSE2). Worked out at start-up; read
// from another static initialiser it may still be false, which picks the portable kernels.
extern const bool kHasAvx;

}  // namespace s4d::cpu
