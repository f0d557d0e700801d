# Fuzz targets (libFuzzer, built with clang++ and ASan+UBSan next to the g++ build), each run for a
# bounded time by CTest from the committed seed corpus. QR_FUZZ_SECONDS sets the time per target.
set(QR_FUZZ_SECONDS 60 CACHE STRING "Seconds each fuzz target runs in the test suite")
find_program(QR_CLANGXX NAMES clang++ clang++-14)
if(NOT QR_CLANGXX)
  message(STATUS "NOTICE: clang++ not found, the fuzz targets are not built")
  return()
endif()
set(_qr_fuzz_dir ${CMAKE_CURRENT_BINARY_DIR}/fuzz)
file(MAKE_DIRECTORY ${_qr_fuzz_dir})
foreach(target fuzz_read_mesh)
  set(src ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/${target}.cpp)
  add_custom_command(OUTPUT ${_qr_fuzz_dir}/${target}
    COMMAND ${QR_CLANGXX} -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined
            -I${PROJECT_SOURCE_DIR}/include -I${EIGEN3_INCLUDE_DIR} ${src} -o ${_qr_fuzz_dir}/${target} -lgmp -lmpfr
    DEPENDS ${src} ${PROJECT_SOURCE_DIR}/include/CGAL/Quad_remeshing/IO.h
    COMMENT "Building the fuzz target ${target} with clang++"
    VERBATIM)
  add_custom_target(${target} ALL DEPENDS ${_qr_fuzz_dir}/${target})
  # runs from a fresh copy of the seed corpus so that the source tree is never written
  add_test(NAME ${target}
           COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=1
                   sh -c "rm -rf corpus_${target} && cp -r ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus corpus_${target} && ./${target} corpus_${target} -max_total_time=${QR_FUZZ_SECONDS} -timeout=20 -rss_limit_mb=4000 -print_final_stats=1"
           WORKING_DIRECTORY ${_qr_fuzz_dir})
  set_tests_properties(${target} PROPERTIES TIMEOUT 900)
endforeach()
