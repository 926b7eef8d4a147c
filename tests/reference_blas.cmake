# Included at the end of tests/unit and tests/runs.
# The .output files of unit/ and runs/ are compared digit by digit and pin
# iteration counts, and the semismooth Newton path can depend on round-off
# (measured: OpenBLAS instead of the reference BLAS turns 9, 9 iterations of
# a thin-plate run into 14, 8 with identical results). These exact-output
# tests therefore run
#  - with Debian's reference BLAS/LAPACK, which computes the same on every
#    x86-64 CPU, whatever BLAS the system selects (tests/setup.sh installs
#    OpenBLAS for the main job and the benchmarks), and
#  - with one deal.II thread: deal.II splits dot products and norms of
#    vectors longer than 16k entries by thread count, so their last bits
#    depend on it.
# The verification tests, which check against tolerances, run with the
# system's BLAS and all threads, except those whose expectations depend on
# the Newton path (whether a stopping rule fires on a cycle), which name
# themselves in _REFERENCE_BLAS_TESTS before including this file.
# (LD_LIBRARY_PATH is taken at configure time.)
set(_ref_blas "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/blas")
set(_ref_lapack "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/lapack")
if(DEFINED _REFERENCE_BLAS_TESTS)
  set(_tests ${_REFERENCE_BLAS_TESTS})
else()
  get_property(_tests DIRECTORY PROPERTY TESTS)
endif()
foreach(_t ${_tests})
  set_property(TEST ${_t} APPEND PROPERTY ENVIRONMENT "DEAL_II_NUM_THREADS=1")
endforeach()
if(EXISTS "${_ref_blas}/libblas.so.3" AND EXISTS "${_ref_lapack}/liblapack.so.3")
  set(_path "${_ref_blas}:${_ref_lapack}")
  if(NOT "$ENV{LD_LIBRARY_PATH}" STREQUAL "")
    set(_path "${_path}:$ENV{LD_LIBRARY_PATH}")
  endif()
  foreach(_t ${_tests})
    set_property(TEST ${_t} APPEND PROPERTY ENVIRONMENT "LD_LIBRARY_PATH=${_path}")
  endforeach()
else()
  message(WARNING "Debian's reference BLAS/LAPACK not found under ${_ref_blas}: "
    "the exact outputs of tests/unit and tests/runs may differ with another BLAS")
endif()
