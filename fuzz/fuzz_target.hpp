// The one shape of every libFuzzer target in fuzz/: bytes in, the parser run on them, and
// s4d::Error the only way it may refuse. Any other exception escapes and aborts, so libFuzzer
// reports it like a crash; so do sanitizer reports, hangs (-timeout) and huge allocations
// (-rss_limit_mb, -malloc_limit_mb).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"

#define S4D_FUZZ_TARGET(text)                                                          \
  static void s4d_fuzz_one(std::string_view text);                                     \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {  \
    try {                                                                              \
      s4d_fuzz_one(std::string_view(reinterpret_cast<const char*>(data), size));       \
    } catch (const s4d::Error&) {                                                      \
    }                                                                                  \
    return 0;                                                                          \
  }                                                                                    \
  static void s4d_fuzz_one(std::string_view text)
