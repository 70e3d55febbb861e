// Whether this test program is built under a sanitizer (tests/configs/asan-ubsan.sh, tsan.sh),
// for the few cases that do less there, each saying why where it asks: a measurement the
// sanitizers' allocators would skew, or work whose checking does not need its full count.
#pragma once

namespace testing_support {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderAddressSanitizer = true;
#else
inline constexpr bool kUnderAddressSanitizer = false;
#endif

#if defined(__SANITIZE_THREAD__)
inline constexpr bool kUnderThreadSanitizer = true;
#else
inline constexpr bool kUnderThreadSanitizer = false;
#endif

// Either of the two (UBSan alone, which only the ASan build carries, changes neither).
inline constexpr bool kUnderSanitizer = kUnderAddressSanitizer || kUnderThreadSanitizer;

}  // namespace testing_support
