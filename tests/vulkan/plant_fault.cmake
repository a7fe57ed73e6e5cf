# Writes a copy of a shader with one planted change: cmake -DSRC=... -DOUT=... -DFROM=... -DTO=...
# -P plant_fault.cmake. FROM must occur exactly once in SRC, so that a kernel edit that moves the
# planted line fails the build instead of leaving a test that plants nothing.
file(READ "${SRC}" text)
string(REPLACE "${FROM}" "" without "${text}")
string(LENGTH "${text}" full)
string(LENGTH "${without}" rest)
string(LENGTH "${FROM}" one)
math(EXPR occurrences "(${full} - ${rest}) / ${one}")
if(NOT occurrences EQUAL 1)
  message(FATAL_ERROR "${SRC}: '${FROM}' occurs ${occurrences} times, not once; update the planted "
                      "fault in tests/vulkan/CMakeLists.txt")
endif()
string(REPLACE "${FROM}" "${TO}" planted "${text}")
if(planted STREQUAL text)
  message(FATAL_ERROR "${SRC}: replacing '${FROM}' by '${TO}' changes nothing")
endif()
file(WRITE "${OUT}.tmp" "${planted}")
file(RENAME "${OUT}.tmp" "${OUT}")
