#include "kernel/analysis/traced_branch.hpp"

namespace rigidfold {

const char* to_string(StopReason r) {
  switch (r) {
    case StopReason::kNone: return "not traced";
    case StopReason::kTargetReached: return "target driving angle reached";
    case StopReason::kFoldLimit: return "fold limit";
    case StopReason::kSignSwitch: return "sign switch";
    case StopReason::kGlobalInterference: return "global interference";
    case StopReason::kSingularPoint: return "singular point";
    case StopReason::kBifurcation: return "bifurcation";
    case StopReason::kBifurcationNotLocated: return "bifurcation (not located)";
    case StopReason::kKnownPoint: return "reached a known point";
    case StopReason::kClosedLoop: return "closed loop";
    case StopReason::kTurningPoint: return "turning point of the driving crease";
    case StopReason::kDepartureFailed: return "departure failed";
    case StopReason::kCorrectorFailed: return "corrector failed";
    case StopReason::kContinuationFailed: return "continuation stopped";
    case StopReason::kMaxPoints: return "max points";
  }
  return "?";
}

const char* to_string(PointKind k) {
  switch (k) {
    case PointKind::kFlat: return "flat";
    case PointKind::kBifurcation: return "bifurcation";
    case PointKind::kFullyFolded: return "fully folded";
    case PointKind::kInterference: return "interference";
  }
  return "?";
}

std::string TracedBranch::stop_text() const {
  std::string s = to_string(stopped_by);
  if (!stop_message.empty()) s += " (" + stop_message + ")";
  return s;
}

}  // namespace rigidfold
