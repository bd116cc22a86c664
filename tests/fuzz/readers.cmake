# The reader registry's mutation test, its corpus tool and (with clang) its libFuzzer target.
# Included from tests/fuzz/CMakeLists.txt before its clang-only part: the mutation test and the
# tool are built by every compiler; reader_fuzz only where -fsanitize=fuzzer links.

set(reader_fuzz_dir "${CMAKE_CURRENT_LIST_DIR}")
add_library(marsokhod_reader_registry STATIC "${reader_fuzz_dir}/mutation_engine.cpp"
                                             "${reader_fuzz_dir}/placement_reader.cpp"
                                             "${reader_fuzz_dir}/reader_targets.cpp"
                                             "${reader_fuzz_dir}/reader_verdict.cpp")
target_include_directories(marsokhod_reader_registry PUBLIC "${CMAKE_SOURCE_DIR}/tests")
target_link_libraries(marsokhod_reader_registry PUBLIC marsokhod_overswitch marsokhod_nav_program marsokhod_occam_port marsokhod_emulator
                      marsokhod_eval marsokhod_nav marsokhod_world marsokhod_imaging marsokhod_io
                      fmt::fmt tomlplusplus::tomlplusplus nlohmann_json::nlohmann_json)
target_compile_definitions(
  marsokhod_reader_registry
  PRIVATE MARSOKHOD_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
          MARSOKHOD_FUZZ_TOOL="$<TARGET_FILE:reader_corpus>"
  PUBLIC MARSOKHOD_FUZZ_OUTPUT="${CMAKE_CURRENT_BINARY_DIR}")

add_executable(reader_corpus "${reader_fuzz_dir}/reader_corpus.cpp")
target_link_libraries(reader_corpus PRIVATE marsokhod_reader_registry)

# tests/CMakeLists.txt names test executables <folder>_<file stem>.
add_executable(fuzz_reader_mutation_test "${reader_fuzz_dir}/reader_mutation_test.cpp")
target_link_libraries(fuzz_reader_mutation_test PRIVATE marsokhod_reader_registry GTest::gtest
                                                        GTest::gtest_main)
add_dependencies(fuzz_reader_mutation_test reader_corpus)
gtest_discover_tests(fuzz_reader_mutation_test DISCOVERY_TIMEOUT 60
                     PROPERTIES LABELS fuzz TIMEOUT 300)

# The real command line on mutated files and fixed hostile files (scripts/hostile-cli.sh).
add_test(NAME fuzz.hostile_cli
         COMMAND sh "${CMAKE_SOURCE_DIR}/scripts/hostile-cli.sh" --count 8 --seed 1
                 --out "${CMAKE_CURRENT_BINARY_DIR}/hostile-cli" --binary $<TARGET_FILE:marsokhod>
                 --tool $<TARGET_FILE:reader_corpus>)
set_tests_properties(fuzz.hostile_cli PROPERTIES LABELS fuzz TIMEOUT 120)

# libFuzzer: one binary, the reader chosen by -reader=NAME (docs/testing.md).
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS "-fsanitize=fuzzer")
  check_cxx_source_compiles(
    [[
#include <cstddef>
#include <cstdint>
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }
]]
    MARSOKHOD_HAVE_LIBFUZZER)
  unset(CMAKE_REQUIRED_FLAGS)
  if(MARSOKHOD_HAVE_LIBFUZZER)
    add_executable(reader_fuzz "${reader_fuzz_dir}/reader_fuzz.cpp")
    target_link_libraries(reader_fuzz PRIVATE marsokhod_reader_registry)
    target_compile_options(reader_fuzz PRIVATE -fsanitize=fuzzer)
    target_link_options(reader_fuzz PRIVATE -fsanitize=fuzzer)
    # A short seeded run of every reader from its seeds; new inputs stay in the build folder.
    add_test(NAME fuzz.reader_smoke
             COMMAND sh -c [[
status=0
for reader in $("$0" list | cut -d' ' -f1); do
  mkdir -p "$2/seeds/$reader" "$2/corpus/$reader"
  "$0" seeds "$reader" "$2/seeds/$reader"
  "$1" -reader="$reader" -seed=1 -runs=3000 -dict="$3" -artifact_prefix="$2/$reader-" \
    "$2/corpus/$reader" "$2/seeds/$reader" || status=1
done
exit $status]]
                     $<TARGET_FILE:reader_corpus> $<TARGET_FILE:reader_fuzz>
                     "${CMAKE_CURRENT_BINARY_DIR}/reader_fuzz_runs" "${reader_fuzz_dir}/readers.dict")
    set_tests_properties(fuzz.reader_smoke PROPERTIES LABELS fuzz TIMEOUT 300)
  endif()
endif()
