#include "core/cpu.hpp"

namespace s4d::cpu {

#if S4D_X86
// This initialiser may run before libgcc's, which fills the data __builtin_cpu_supports reads.
const bool kHasAvx = (__builtin_cpu_init(), __builtin_cpu_supports("avx"));
#else
const bool kHasAvx = false;
#endif

}  // namespace s4d::cpu
