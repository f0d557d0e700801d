# The package installs, and an out-of-tree application finds it with find_package(CGAL_Quad_remeshing).
add_test(NAME install_and_consume
         COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR}
                 -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/install_consumer
                 -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/install_consumer
                 -DMESH=${QR_DATA_DIR}/meshes/xyz_cube_20mm.off
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/install_consumer/run.cmake)
set_tests_properties(install_and_consume PROPERTIES TIMEOUT 600 PASS_REGULAR_EXPRESSION "\"F\":260")
