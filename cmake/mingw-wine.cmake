# Toolchain of the Windows test build (scripts/windows/test.sh): the C and C++ programs of
# c-tests/ compiled with MinGW-w64 for MCCL_WINDOWS_ARCH (x64 or x86, given with -D) and
# run by CTest under Wine (CMakeLists.txt sets the wrapper as the emulator).
set(CMAKE_SYSTEM_NAME Windows)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES MCCL_WINDOWS_ARCH)
if(MCCL_WINDOWS_ARCH STREQUAL "x86")
  set(CMAKE_SYSTEM_PROCESSOR i686)
  set(MCCL_MINGW i686-w64-mingw32)
elseif(MCCL_WINDOWS_ARCH STREQUAL "x64")
  set(CMAKE_SYSTEM_PROCESSOR x86_64)
  set(MCCL_MINGW x86_64-w64-mingw32)
else()
  message(FATAL_ERROR "MCCL_WINDOWS_ARCH must be x64 or x86, not '${MCCL_WINDOWS_ARCH}'")
endif()
# The -posix compilers: their runtime has the POSIX threads and clocks (pthread,
# clock_gettime, nanosleep, std::mutex) some test programs use.
set(CMAKE_C_COMPILER ${MCCL_MINGW}-gcc-posix)
set(CMAKE_CXX_COMPILER ${MCCL_MINGW}-g++-posix)
set(CMAKE_RC_COMPILER ${MCCL_MINGW}-windres)
set(CMAKE_FIND_ROOT_PATH /usr/${MCCL_MINGW})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
# Programs that need no MinGW runtime DLL (libgcc, libstdc++, winpthread) beside them: the
# only DLL they load that Windows lacks is MCCLPCI_IMP.dll.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
