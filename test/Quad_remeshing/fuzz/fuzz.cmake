# Fuzz targets (libFuzzer, built with clang++ and ASan+UBSan next to the g++ build), each run by CTest
# from the committed seed corpus for a fixed number of inputs from seed 1.
find_program(QR_CLANGXX NAMES clang++ clang++-14)
if(NOT QR_CLANGXX)
  message(STATUS "NOTICE: clang++ not found, the fuzz targets are not built")
  return()
endif()
# Both targets run a fixed number of inputs from a fixed seed: the same inputs on any machine, so the
# test command's result does not depend on the machine's speed nor on chance (a random 60 s run of the
# readers once found an input that a later run missed; long random runs are a developer's job, see
# CONTRIBUTING.md, and what they find goes into the corpus).
set(QR_FUZZ_READ_RUNS 20000 CACHE STRING "Inputs the reader fuzz target runs in the test suite")
set(QR_FUZZ_PIPELINE_RUNS 100 CACHE STRING "Inputs the whole-pipeline fuzz target runs in the test suite")
set(_qr_fuzz_dir ${CMAKE_CURRENT_BINARY_DIR}/fuzz)
file(MAKE_DIRECTORY ${_qr_fuzz_dir})
# fuzz_read_mesh: the mesh readers and the repair (any bytes as an OFF/OBJ/PLY/STL file);
# fuzz_quad_remesh: the whole pipeline on tiny triangle soups (GLPK and Eigen as in the package)
set(_qr_fuzz_read_mesh_flags "")
set(_qr_fuzz_read_mesh_libs -lgmp -lmpfr)
set(_qr_fuzz_read_mesh_corpus corpus)
set(_qr_fuzz_read_mesh_limits "-seed=1 -runs=${QR_FUZZ_READ_RUNS}")
set(_qr_fuzz_quad_remesh_flags -DCGAL_EIGEN3_ENABLED -DCGAL_USE_GLPK -pthread)
set(_qr_fuzz_quad_remesh_libs -lglpk -lgmp -lmpfr)
set(_qr_fuzz_quad_remesh_corpus corpus_pipeline)
set(_qr_fuzz_quad_remesh_limits "-seed=1 -runs=${QR_FUZZ_PIPELINE_RUNS}")
foreach(name read_mesh quad_remesh)
  set(target fuzz_${name})
  set(src ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/${target}.cpp)
  file(GLOB_RECURSE _qr_headers ${PROJECT_SOURCE_DIR}/include/CGAL/*.h)
  add_custom_command(OUTPUT ${_qr_fuzz_dir}/${target}
    COMMAND ${QR_CLANGXX} -std=c++17 -g1 -O1 -fsanitize=fuzzer,address,undefined
            ${_qr_fuzz_${name}_flags}
            -I${PROJECT_SOURCE_DIR}/include -I${EIGEN3_INCLUDE_DIR} ${src} -o ${_qr_fuzz_dir}/${target}
            ${_qr_fuzz_${name}_libs}
    DEPENDS ${src} ${_qr_headers}
    COMMENT "Building the fuzz target ${target} with clang++"
    VERBATIM)
  add_custom_target(${target} ALL DEPENDS ${_qr_fuzz_dir}/${target})
  # runs from a fresh copy of the seed corpus so that the source tree is never written
  set(corpus ${_qr_fuzz_${name}_corpus})
  add_test(NAME ${target}
           COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=1
                   sh -c "rm -rf ${target}_${corpus} && cp -r ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/${corpus} ${target}_${corpus} && ./${target} ${target}_${corpus} ${_qr_fuzz_${name}_limits} -timeout=20 -rss_limit_mb=4000 -print_final_stats=1"
           WORKING_DIRECTORY ${_qr_fuzz_dir})
  set_tests_properties(${target} PROPERTIES TIMEOUT 900)
endforeach()
