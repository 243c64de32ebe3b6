# Cross-building ODE Lab for 64-bit Windows with Debian's MinGW-w64:
#
#   cmake -S . -B build-windows -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64-x86_64.cmake \
#         -DODELAB_WINDOWS_PREFIX=<prefix from scripts/windows/deps.sh>
#
# scripts/windows/build.sh does all of it. The libraries come from the prefix
# only, through its pkg-config files; nothing of the build machine's is used.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(ODELAB_WINDOWS_HOST x86_64-w64-mingw32)

# The -posix compilers: MinGW's win32 thread model has no std::thread.
set(CMAKE_C_COMPILER ${ODELAB_WINDOWS_HOST}-gcc-posix)
set(CMAKE_CXX_COMPILER ${ODELAB_WINDOWS_HOST}-g++-posix)
set(CMAKE_RC_COMPILER ${ODELAB_WINDOWS_HOST}-windres)

set(ODELAB_WINDOWS_PREFIX "$ENV{ODELAB_WINDOWS_PREFIX}" CACHE PATH
    "The prefix scripts/windows/deps.sh built the libraries into")
if(NOT ODELAB_WINDOWS_PREFIX OR NOT EXISTS "${ODELAB_WINDOWS_PREFIX}/lib/pkgconfig")
  message(FATAL_ERROR "ODELAB_WINDOWS_PREFIX ('${ODELAB_WINDOWS_PREFIX}') holds no libraries: "
                      "run scripts/windows/deps.sh and pass the folder it prints.")
endif()
# Try-compiles see the prefix too.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES ODELAB_WINDOWS_PREFIX)

set(CMAKE_FIND_ROOT_PATH ${ODELAB_WINDOWS_PREFIX} /usr/${ODELAB_WINDOWS_HOST})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# pkg-config reads the prefix's files alone; --static: the libraries are
# static, so each brings the Windows libraries it needs.
set(ENV{PKG_CONFIG_LIBDIR} "${ODELAB_WINDOWS_PREFIX}/lib/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")
set(PKG_CONFIG_ARGN --static)
