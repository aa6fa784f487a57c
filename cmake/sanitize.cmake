# Sanitizer build (scripts/sanitize.sh): AddressSanitizer and UndefinedBehaviorSanitizer on every
# target, with undefined behaviour fatal (no recovery), so one report fails the test that caused it.
# Meant for Debug, where Eigen's and libstdc++'s own assertions are on as well.
option(IGA_SANITIZE "Build everything with -fsanitize=address,undefined (see scripts/sanitize.sh)" OFF)
if(IGA_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
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
