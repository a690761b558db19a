# rigidfold_compile_time(TARGET [GTEST] [CLI] [UNITY N]): the heavy headers that most translation units
# include (Eigen, nlohmann-json, the standard library; GoogleTest and CLI11 where asked),
# precompiled once per target instead of parsed once per file. Parsing them took about half of
# a light file's compile time (crease_energy.cpp: 6.9 s -> 3.7 s, g++ 12 -O3); the heavy files
# spend theirs instantiating and optimising Eigen's decompositions, which a unity build did not
# share either (twelve kernel files took as long in one unit as one by one).
# UNITY N: the target's files compiled N to a unit. Where the files' code is mostly the same
# libraries' templates (the commands' CLI11 and nlohmann-json code, the tests' GoogleTest and
# JSON), each unit generates it once instead of once per file: app/'s 26 files took 565 s of CPU
# one by one and 156 s in two units (clang 14, ASan + UBSan, -O2). Names at file scope must then
# differ between the files of a target (a file's anonymous namespace is shared with its unit):
# the tests keep theirs in `namespace { namespace RIGIDFOLD_UNITY_ID {`, a name unique to each
# file in a unit (CMake's UNITY_BUILD_UNIQUE_ID) and empty otherwise.
# The decompositions of kernel/math/eigen_instantiations.hpp are declared extern in every unit,
# so that their code is compiled once (tangent_cone.cpp: 87 s -> 28 s, clang 14, ASan + UBSan).
# Every source still includes what it uses: the header is forced in first, it does not replace
# a file's own includes. -DRIGIDFOLD_PRECOMPILED_HEADERS=OFF turns both off (to check that every
# file compiles on its own includes).
option(RIGIDFOLD_PRECOMPILED_HEADERS "Precompile the common heavy headers of each target, and compile in unity units where asked" ON)

function(rigidfold_compile_time target)
  cmake_parse_arguments(FAST "GTEST;CLI" "UNITY" "" ${ARGN})
  if(FAST_UNITY AND NOT RIGIDFOLD_PRECOMPILED_HEADERS)
    target_compile_definitions(${target} PRIVATE RIGIDFOLD_UNITY_ID=)
  endif()
  if(NOT RIGIDFOLD_PRECOMPILED_HEADERS)
    return()
  endif()
  if(FAST_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${FAST_UNITY}
                                               UNITY_BUILD_UNIQUE_ID RIGIDFOLD_UNITY_ID)
  endif()
  set(headers
    <algorithm> <array> <cmath> <cstdint> <cstdio> <filesystem> <fstream> <functional> <iostream>
    <limits> <map> <memory> <numbers> <optional> <random> <set> <sstream> <stdexcept> <string>
    <utility> <vector>
    <Eigen/Core> <Eigen/Dense> <Eigen/SparseCore> <nlohmann/json.hpp>
    # Eigen's dense decompositions declared extern: compiled once, in the kernel library.
    "${PROJECT_SOURCE_DIR}/kernel/math/eigen_instantiations.hpp")
  if(FAST_GTEST)
    list(APPEND headers <gtest/gtest.h>)
  endif()
  if(FAST_CLI)
    list(APPEND headers <CLI/CLI.hpp>)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
