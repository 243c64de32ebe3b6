# ODELAB_ODE_ROOT: build the programs against an ODE other than the system's.
# An install prefix: its pkg-config file is put first on PKG_CONFIG_PATH and
# found as usual. A source tree built in place (autotools: configure && make):
# PkgConfig::ODE is made from its include/ and the library make left, and
# ODE_PRECISION from the dDOUBLE that configure wrote into precision.h.
if(NOT ODELAB_ODE_ROOT)
  return()
endif()
get_filename_component(ODELAB_ODE_ROOT "${ODELAB_ODE_ROOT}" ABSOLUTE)
if(NOT EXISTS "${ODELAB_ODE_ROOT}/include/ode/ode.h")
  message(FATAL_ERROR "ODELAB_ODE_ROOT=${ODELAB_ODE_ROOT}: no include/ode/ode.h there; give an ODE install "
                      "prefix or a source tree built with configure && make")
endif()
# An ODE before 0.12 (no threading API in ode.h): the programs are built
# with cmake/ode-before-0.12/ode_before_0_12.h force-included (its first comment
# says why), and that folder ahead on the include path for ode/threading_impl.h.
macro(odelab_ode_compatibility)
  include(CheckCXXSourceCompiles)
  get_target_property(ODELAB_ODE_INCLUDES PkgConfig::ODE INTERFACE_INCLUDE_DIRECTORIES)
  set(CMAKE_REQUIRED_INCLUDES ${ODELAB_ODE_INCLUDES})
  set(CMAKE_REQUIRED_DEFINITIONS ${ODE_CFLAGS_OTHER})
  check_cxx_source_compiles("#include <ode/ode.h>
int main() { dThreadingImplementationID id = 0; return id != 0; }" ODELAB_ODE_HAS_THREADING)
  unset(CMAKE_REQUIRED_INCLUDES)
  unset(CMAKE_REQUIRED_DEFINITIONS)
  if(NOT ODELAB_ODE_HAS_THREADING)
    target_compile_options(PkgConfig::ODE INTERFACE
                           "SHELL:-include ${CMAKE_CURRENT_LIST_DIR}/ode-before-0.12/ode_before_0_12.h")
    target_include_directories(PkgConfig::ODE BEFORE INTERFACE "${CMAKE_CURRENT_LIST_DIR}/ode-before-0.12")
    target_compile_definitions(PkgConfig::ODE INTERFACE "ODELAB_ODE_VERSION=\"${ODELAB_ODE_VERSION_TEXT}\"")
    message(STATUS "ODE has no threading API (before 0.12): building with cmake/ode-before-0.12/")
  endif()
endmacro()

# dDOUBLE or dSINGLE, from the precision.h configure wrote (or ode.pc's flags).
macro(odelab_precision_from_header)
  set(ODELAB_ODE_DOUBLE "")
  if(EXISTS "${ODELAB_ODE_ROOT}/include/ode/precision.h")
    file(STRINGS "${ODELAB_ODE_ROOT}/include/ode/precision.h" ODELAB_ODE_DOUBLE REGEX "^#define dDOUBLE")
  elseif("-DdDOUBLE" IN_LIST ODE_CFLAGS_OTHER)  # ODE 0.11 passed the precision as a flag (ode.pc)
    set(ODELAB_ODE_DOUBLE 1)
  endif()
  if(ODELAB_ODE_DOUBLE)
    set(ODE_PRECISION dDOUBLE)
  else()
    set(ODE_PRECISION dSINGLE)
  endif()
endmacro()

file(GLOB ODELAB_ODE_PC_DIRS "${ODELAB_ODE_ROOT}/lib*/pkgconfig" "${ODELAB_ODE_ROOT}/lib/*/pkgconfig")
foreach(dir IN LISTS ODELAB_ODE_PC_DIRS)
  if(EXISTS "${dir}/ode.pc")
    set(ENV{PKG_CONFIG_PATH} "${dir}:$ENV{PKG_CONFIG_PATH}")
    pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)
    pkg_get_variable(ODE_PRECISION ode precision)
    if(NOT ODE_PRECISION)  # older ode.pc files (0.11) name no precision
      odelab_precision_from_header()
    endif()
    message(STATUS "ODE from ${dir}/ode.pc: ${ODE_VERSION}, ${ODE_PRECISION}")
    set(ODELAB_ODE_VERSION_TEXT "${ODE_VERSION}")
    odelab_ode_compatibility()
    return()
  endif()
endforeach()
find_library(ODELAB_ODE_LIBRARY NAMES ode
             PATHS "${ODELAB_ODE_ROOT}/ode/src/.libs" "${ODELAB_ODE_ROOT}/lib" "${ODELAB_ODE_ROOT}/build"
             NO_DEFAULT_PATH)
if(NOT ODELAB_ODE_LIBRARY)
  message(FATAL_ERROR "ODELAB_ODE_ROOT=${ODELAB_ODE_ROOT}: no libode under ode/src/.libs, lib or build; "
                      "build the source tree first (./configure --enable-double-precision && make)")
endif()
find_package(Threads REQUIRED)
add_library(PkgConfig::ODE INTERFACE IMPORTED)
target_include_directories(PkgConfig::ODE INTERFACE "${ODELAB_ODE_ROOT}/include")
target_link_libraries(PkgConfig::ODE INTERFACE "${ODELAB_ODE_LIBRARY}" Threads::Threads)
set(ODE_INCLUDE_DIRS "${ODELAB_ODE_ROOT}/include")
odelab_precision_from_header()
set(ODELAB_ODE_VERSION_TEXT "unknown")
odelab_ode_compatibility()
message(STATUS "ODE from the source tree ${ODELAB_ODE_ROOT}: ${ODELAB_ODE_LIBRARY}, ${ODE_PRECISION}")
