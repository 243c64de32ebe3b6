// The extreme-settings grid: which world settings each program is run with
// (checks/extreme_settings.cpp runs them; checks/hardening.cmake registers
// one CTest row per setting and program).
//
// Settings: step 1e-5, 1e-4, 1e-3, 1e-2, 0.1 s; ERP 0, 0.5, 1; CFM 0, 1e-3, 1;
// iterations 1, 20, 1000; solver quick, step. Their full product (270 per
// program) is too slow for CI, so each program gets a pairwise covering set
// (15 rows in which every value of every parameter meets every value of every
// other; gridSettings() checks it) plus the extreme corners listed in
// CORNERS: 21 settings.
#pragma once

#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace extreme {

const std::vector<double> STEPS{1e-5, 1e-4, 1e-3, 1e-2, 0.1};
const std::vector<double> ERPS{0.0, 0.5, 1.0};
const std::vector<double> CFMS{0.0, 1e-3, 1.0};
const std::vector<int> ITERATIONS{1, 20, 1000};
const std::vector<std::string> SOLVERS{"quick", "step"};

struct Settings {
  double step, erp, cfm;
  int iterations;
  std::string solver;
  std::string label;  // "pairwise" or what the corner stands for
};

// The corners that a pairwise set may miss: each end of the step range with
// the settings that stress it most.
const std::vector<Settings> CORNERS{
    {1e-5, 1.0, 0.0, 1000, "quick", "corner: smallest step, most iterations, rigid"},
    {1e-5, 0.0, 0.0, 1, "quick", "corner: smallest step, no correction, one iteration"},
    {1e-5, 0.0, 1.0, 20, "step", "corner: smallest step, softest, dWorldStep"},
    {0.1, 1.0, 0.0, 20, "quick", "corner: largest step, ERP 1, CFM 0"},
    {0.1, 1.0, 0.0, 20, "step", "corner: largest step, ERP 1, CFM 0, dWorldStep"},
    {0.1, 0.0, 0.0, 1, "quick", "corner: largest step, no correction, one iteration"},
    {0.1, 1.0, 1.0, 1000, "quick", "corner: largest step, softest, most iterations"},
    {0.1, 0.0, 1.0, 1, "step", "corner: largest step, softest, dWorldStep"},
};

// Rows (i, j), i over the 5 steps and j over the 3 ERPs: CFM (i+j) mod 3,
// iterations (j+2i) mod 3, solver (i+j) mod 2.
inline std::vector<Settings> pairwiseRows() {
  std::vector<Settings> rows;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j)
      rows.push_back({STEPS[i], ERPS[j], CFMS[(i + j) % 3], ITERATIONS[(j + 2 * i) % 3], SOLVERS[(i + j) % 2],
                      "pairwise"});
  return rows;
}

// True when every pair of values of every two parameters occurs in `rows`.
inline bool coversEveryPair(const std::vector<Settings>& rows) {
  auto levels = [](const Settings& s) {
    return std::vector<std::string>{std::to_string(s.step), std::to_string(s.erp), std::to_string(s.cfm),
                                    std::to_string(s.iterations), s.solver};
  };
  const std::vector<size_t> sizes{STEPS.size(), ERPS.size(), CFMS.size(), ITERATIONS.size(), SOLVERS.size()};
  for (size_t a = 0; a < sizes.size(); ++a)
    for (size_t b = a + 1; b < sizes.size(); ++b) {
      std::set<std::pair<std::string, std::string>> seen;
      for (const auto& row : rows) seen.insert({levels(row)[a], levels(row)[b]});
      if (seen.size() != sizes[a] * sizes[b]) return false;
    }
  return true;
}

// The pairwise rows, then the corners they lack (a corner they hold only
// names its row), in a fixed order: setting i is the same run every time.
// Throws std::logic_error if the pairwise rows miss a pair.
inline std::vector<Settings> gridSettings() {
  const std::vector<Settings> pairwise = pairwiseRows();
  if (!coversEveryPair(pairwise)) throw std::logic_error("the pairwise rows do not cover every pair of values");
  std::vector<Settings> cases = pairwise;
  for (const auto& corner : CORNERS) {
    bool present = false;
    for (auto& c : cases)
      if (c.step == corner.step && c.erp == corner.erp && c.cfm == corner.cfm && c.iterations == corner.iterations &&
          c.solver == corner.solver) {
        c.label = corner.label;
        present = true;
      }
    if (!present) cases.push_back(corner);
  }
  return cases;
}

}  // namespace extreme
