#pragma once
// The documented limits on user input. Every size-driven read or allocation that user input
// controls is checked against one of these before it is made; going past one is bad input
// (InputError naming the file, JSON path or flag; the CLI exits 2). README, "Bad input and
// limits", lists them.
#include <cstddef>
#include <cstdint>

namespace rigidfold {

// Readers (kernel/pattern/json_input.hpp): every JSON input (FOLD, angles, string spec and
// target) is read from a regular file of at most kMaxInputFileBytes, and its arrays and
// objects may nest at most kMaxJsonDepth deep (the top-level object is depth 1). Deeper
// documents are refused at parse time, so no later recursive copy, dump or comparison of
// kept keys can overflow the stack.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{256} << 20;  // 256 MiB
inline constexpr int kMaxJsonDepth = 512;

// `rigidfold trace`: at most kMaxTraceSteps steps, and at most kMaxTraceStepValues stored
// values, steps x (edges + 3 x vertices + 16 x faces): every step keeps its fold angles,
// placed vertices and face motions, and --out writes them all. Measured (Release): 5000
// steps of the 4 x 4 Miura (1.9e6 values) take 0.95 s and 89 MB (~47 bytes a value, so the
// limit is ~1.4 GB). 3e7 and not less: the peer comparison's 30-step trace of a
// 100 x 100 Miura (docs/benchmarks.md) stores 6.3e6 values (5e6 refused it).
inline constexpr int kMaxTraceSteps = 10000;
inline constexpr std::int64_t kMaxTraceStepValues = 30000000;

// `rigidfold string forward|design`: vertices of one origami string (spec or target
// "vertices"; forward at the limit: 1.2 s), vertices of a curve target (points - 2; closed
// form at the limit: 0.6 s) and of a curve fitted by NLopt (its time grows steeply: 30
// vertices 5.4 s, 7.2 s with the global stage; 60 vertices 33 s; 100 vertices hit the 60 s
// time cap), samples of a trajectory target (theta_deg entries),
// and vertex-samples of a trajectory fit (vertices x samples).
inline constexpr int kMaxStringVertices = 20000;
inline constexpr int kMaxCurveDesignVertices = 2000;
inline constexpr int kMaxNloptCurveVertices = 30;
inline constexpr int kMaxTrajectorySamples = 2000;
inline constexpr std::int64_t kMaxTrajectoryValues = 200000;

// `rigidfold generate`: cells (--rows x --cols) of a Miura-ori (about 2 creases per cell;
// 500 x 500 cells, 501000 creases: 5.2 s) and of a square-twist tessellation (about 8 creases
// per cell; 100 x 100: 1.1 s). 1000 x 1000 Miura cells took 24 s and 864 MB.
inline constexpr std::int64_t kMaxGeneratedMiuraCells = 250000;
inline constexpr std::int64_t kMaxGeneratedTwistCells = 62500;

// SVG crease patterns (svg_reader.hpp; file size as above): elements nested at most
// kMaxSvgDepth deep, at most kMaxSvgElements XML elements and kMaxSvgSegments straight
// segments in crease colours, and at most kMaxSvgCandidatePairs pairs of nearby segments
// tested for crossings (only a pile of overlapping lines comes near it: segments are paired
// only when they share a cell of a grid with ~1 segment per cell).
inline constexpr int kMaxSvgDepth = 256;
inline constexpr int kMaxSvgElements = 2000000;
inline constexpr int kMaxSvgSegments = 500000;
inline constexpr std::int64_t kMaxSvgCandidatePairs = 50000000;

}  // namespace rigidfold
