#include "softtissue/blas_library.h"

#include <dlfcn.h>

#include <filesystem>

namespace maxillo::softtissue {

std::string blas_library() {
  void* dgemm = dlsym(RTLD_DEFAULT, "dgemm_");
  Dl_info info{};
  if (dgemm == nullptr || dladdr(dgemm, &info) == 0 || info.dli_fname == nullptr) return "none loaded";
  std::error_code error;
  auto resolved = std::filesystem::canonical(info.dli_fname, error);
  return error ? std::string(info.dli_fname) : resolved.string();
}

}  // namespace maxillo::softtissue
