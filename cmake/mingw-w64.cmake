# Cross-compiling for 64-bit Windows with Debian's MinGW-w64 (the posix
# thread model, whose libgomp gives OpenMP): scripts/windows uses it.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
# The target's libraries only: MinGW's, and the prefix scripts/windows builds
# the rest into (never the build machine's /usr).
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32 $ENV{ACO_WINDOWS_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# Tests built for Windows run under Wine (ctest runs them through it).
set(CMAKE_CROSSCOMPILING_EMULATOR wine)
