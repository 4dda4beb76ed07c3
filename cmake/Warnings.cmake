add_library(valsalva_warnings INTERFACE)
target_compile_options(valsalva_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow=local
  -Wno-restrict  # GCC 12 false positives in std::string (GCC bug 105329)
  $<$<BOOL:${VALSALVA_WARNINGS_AS_ERRORS}>:-Werror>)
