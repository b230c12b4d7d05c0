# How the project finds its external dependencies (all from Debian packages).
# See third_party/README.md for packages, versions and licenses.
find_library(GMP_LIBRARY NAMES gmp REQUIRED)
find_library(GMPXX_LIBRARY NAMES gmpxx REQUIRED)
find_library(MPFR_LIBRARY NAMES mpfr REQUIRED)
find_path(GMP_INCLUDE_DIR NAMES gmpxx.h REQUIRED)
find_package(CGAL 5.5 REQUIRED)
find_package(Threads REQUIRED)
# oneTBB for the arrangement pipeline's parallel stages; CGAL's module defines
# CGAL::TBB_support (CGAL_LINKED_WITH_TBB, needed by CGAL's Parallel_tag algorithms).
find_package(TBB CONFIG REQUIRED)
include(CGAL_TBB_support)
# Eigen (header-only) for the matrix APIs: tritri/self_intersections.h, tritri/intersections.h,
# arrangements/arrange_eigen.h and the Python module. Debian: libeigen3-dev.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
if(TRITRI_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(TRITRI_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
