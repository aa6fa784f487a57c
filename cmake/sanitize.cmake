# Sanitizer build (scripts/sanitize.sh): AddressSanitizer and UndefinedBehaviorSanitizer on every
# target, with undefined behaviour fatal (no recovery), so one report fails the test that caused it.
# Meant for Debug, where Eigen's and libstdc++'s own assertions are on as well.
option(IGA_SANITIZE "Build everything with -fsanitize=address,undefined (see scripts/sanitize.sh)" OFF)
if(IGA_SANITIZE)
  # -O1: at Debug's -O0 Eigen's expression templates are not inlined and the suite ran ~3 h on two
  # cores (more than a session); AddressSanitizer's own guidance is -O1 for usable speed, and the
  # checks (shadow memory, UBSan's, the assertions below and Eigen's, kept without NDEBUG) stay.
  add_compile_options(-O1 -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined)
  # Bounds checks in std::vector/std::string/... without changing the library ABI (unlike _GLIBCXX_DEBUG,
  # which would not link against the Debian builds of yaml-cpp, VTK or Gmsh).
  add_compile_definitions(_GLIBCXX_ASSERTIONS)
endif()

# Sanitized Debug code runs ten to fifty times slower: each test may take longer before ctest stops it.
if(IGA_SANITIZE)
  set(IGA_TEST_TIMEOUT 7200 CACHE STRING "Seconds each test may run")
else()
  set(IGA_TEST_TIMEOUT 600 CACHE STRING "Seconds each test may run")
endif()

# The rendering test under the sanitizers: Mesa's software GL driver (swrast_dri.so, what Xvfb
# gives) is dlopen'ed by libGL and unloaded at exit while its globals still point at what it
# allocated, so LeakSanitizer reports those blocks as leaked and cannot name the module (it prints
# the test binary instead). Preloading the driver keeps it mapped and the blocks reachable; the
# sanitizer runtime has to come first in the preload list.
set(IGA_RENDER_TEST_LAUNCHER "")
if(IGA_SANITIZE)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so
                  OUTPUT_VARIABLE iga_libasan OUTPUT_STRIP_TRAILING_WHITESPACE)
  find_file(IGA_MESA_SWRAST swrast_dri.so PATHS /usr/lib/x86_64-linux-gnu/dri /usr/lib/dri NO_DEFAULT_PATH)
  if(IGA_MESA_SWRAST AND EXISTS "${iga_libasan}")
    set(IGA_RENDER_TEST_LAUNCHER env "LD_PRELOAD=${iga_libasan} ${IGA_MESA_SWRAST}")
  endif()
endif()
