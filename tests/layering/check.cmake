# Builds layering_right_way (must succeed) and layering_wrong_way (must fail because the
# higher layer's header is not found). Run with -DBINARY_DIR=<build tree>.
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR} --target layering_right_way
                RESULT_VARIABLE right_rc OUTPUT_VARIABLE right_out ERROR_VARIABLE right_out)
if(NOT right_rc EQUAL 0)
  message(FATAL_ERROR "the control case (a planner including world/) does not compile:\n${right_out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR} --target layering_wrong_way
                RESULT_VARIABLE wrong_rc OUTPUT_VARIABLE wrong_out ERROR_VARIABLE wrong_out)
if(wrong_rc EQUAL 0)
  message(FATAL_ERROR "a planner including sim/simulation.hpp compiled: the layers' include roots leak")
endif()
if(NOT wrong_out MATCHES "sim/simulation.hpp: No such file or directory")
  message(FATAL_ERROR "the wrong-way include failed for another reason than the missing header:\n${wrong_out}")
endif()
message(STATUS "wrong-way include refused: sim/simulation.hpp is not visible from the planners layer")
