# rigidfold_compile_time(TARGET [GTEST] [CLI]): the heavy headers that most translation units
# include (Eigen, nlohmann-json, the standard library; GoogleTest and CLI11 where asked),
# precompiled once per target instead of parsed once per file. Parsing them took about half of
# a light file's compile time (crease_energy.cpp: 6.9 s -> 3.7 s, g++ 12 -O3); the heavy files
# spend theirs instantiating and optimising Eigen's decompositions, which a unity build did not
# share either (twelve kernel files took as long in one unit as one by one).
# Every source still includes what it uses: the header is forced in first, it does not replace
# a file's own includes. -DRIGIDFOLD_PRECOMPILED_HEADERS=OFF turns it off (to check that every
# file compiles on its own includes).
option(RIGIDFOLD_PRECOMPILED_HEADERS "Precompile the common heavy headers of each target" ON)

function(rigidfold_compile_time target)
  cmake_parse_arguments(FAST "GTEST;CLI" "" "" ${ARGN})
  if(NOT RIGIDFOLD_PRECOMPILED_HEADERS)
    return()
  endif()
  set(headers
    <algorithm> <array> <cmath> <cstdint> <cstdio> <filesystem> <fstream> <functional> <iostream>
    <limits> <map> <memory> <numbers> <optional> <random> <set> <sstream> <stdexcept> <string>
    <utility> <vector>
    <Eigen/Core> <Eigen/Dense> <Eigen/SparseCore> <nlohmann/json.hpp>)
  if(FAST_GTEST)
    list(APPEND headers <gtest/gtest.h>)
  endif()
  if(FAST_CLI)
    list(APPEND headers <CLI/CLI.hpp>)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
