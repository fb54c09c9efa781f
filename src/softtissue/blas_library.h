#pragma once
// Which BLAS the process runs on. CHOLMOD's supernodal factorisation spends its time in BLAS
// (dgemm, dsyrk, dtrsm), and Debian picks the library at run time through alternatives: the
// reference BLAS factorised the 105k-tet cube in 5.8 s, OpenBLAS (libopenblas0-pthread) in
// 1.0 s, with no change to maxillo. Benchmarks report it so their figures can be compared.
#include <string>

namespace maxillo::softtissue {

// The file that provides dgemm_ (symbolic links resolved), e.g.
// /usr/lib/x86_64-linux-gnu/openblas-pthread/libblas.so.3, or "none loaded".
std::string blas_library();

}  // namespace maxillo::softtissue
