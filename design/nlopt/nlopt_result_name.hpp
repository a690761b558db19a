#pragma once
// NLopt's result code as the word its documentation uses ("XTOL_REACHED"), for the reports of
// the design searches (design/strings, design/sorce) that say why a search stopped.
#include <nlopt.hpp>
#include <string>

namespace rigidfold {

inline std::string nlopt_result_name(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS: return "SUCCESS";
    case nlopt::STOPVAL_REACHED: return "STOPVAL_REACHED";
    case nlopt::FTOL_REACHED: return "FTOL_REACHED";
    case nlopt::XTOL_REACHED: return "XTOL_REACHED";
    case nlopt::MAXEVAL_REACHED: return "MAXEVAL_REACHED";
    case nlopt::MAXTIME_REACHED: return "MAXTIME_REACHED";
    default: return "FAILURE(" + std::to_string(static_cast<int>(r)) + ")";
  }
}

}  // namespace rigidfold
