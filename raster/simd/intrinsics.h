// <immintrin.h>, as every file here includes it. GCC 12's AVX-512 intrinsics start from
// _mm512_undefined_ps() and friends (`__m512 __Y = __Y;`), which -Wuninitialized reports
// wherever one is inlined (GCC bug 105593, fixed in GCC 13). The warning points into the
// intrinsics headers, so silencing it around their include silences only that.
#pragma once

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#else
#include <immintrin.h>   // clang (the fuzz build) does not have the warning
#endif
