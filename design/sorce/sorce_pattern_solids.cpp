#include "design/sorce/sorce_pattern_solids.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>
#include <string>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {
namespace {

namespace bg = boost::geometry;
using BgPoint = bg::model::d2::point_xy<double>;
using BgPolygon = bg::model::polygon<BgPoint>;
using BgMulti = bg::model::multi_polygon<BgPolygon>;

}  // namespace

PatternSolids pattern_solids(const CreasePattern& p, const PatternSorce& s, int samples, const SolidOptions& options,
                             const ClearanceOptions& clearance) {
  const int nf = p.num_faces();
  std::vector<PanelSolidInput> in(nf);
  PatternSolids out;
  out.cam_edge.resize(nf);
  for (int f = 0; f < nf; ++f) {
    for (int v : p.faces[f]) in[f].polygon.push_back(p.vertices[v]);
    in[f].thickness = s.faces[f].thickness;
  }
  for (const CreaseJoint& j : s.creases) {
    if (!j.folds) continue;
    const SampledProfiles prof = sample_profiles(j.motion, samples);
    const Eigen::Vector3d a = p.vertices[p.edges[j.edge][0]], b = p.vertices[p.edges[j.edge][1]];
    for (bool left : {true, false}) {
      CamSide c;
      c.origin = a;
      c.fold_direction = (b - a).normalized();
      c.x_axis = j.frame.linear().col(0);
      c.w0 = 0.0;
      c.w1 = (b - a).norm();
      c.left = left;
      c.profile = left ? prof.left : prof.right;
      const int f = left ? j.left_face : j.right_face;
      in[f].cams.push_back(c);
      out.cam_edge[f].push_back(j.edge);
    }
  }
  auto build = [&] {
    out.panels.clear();
    for (int f = 0; f < nf; ++f) {
      try {
        out.panels.push_back(panel_solid(in[f], options));
      } catch (const InputError& e) {
        throw InputError("faces[" + std::to_string(f) + "]: " + e.place(), e.message());
      }
    }
  };
  build();
  if (!clearance.cut) return out;
  if (!(clearance.margin > 0.0) || !std::isfinite(clearance.margin)) throw InputError("clearance.margin", "must be > 0");
  if (clearance.samples < 2) throw InputError("clearance.samples", "must be >= 2");
  for (const CreaseJoint& j : s.creases) {
    if (!j.folds) continue;
    const Eigen::Vector3d a = p.vertices[p.edges[j.edge][0]], b = p.vertices[p.edges[j.edge][1]];
    for (bool this_left : {true, false}) {
      const int f = this_left ? j.left_face : j.right_face, g = this_left ? j.right_face : j.left_face;
      const PanelSolid& mate = out.panels[g];
      int shell = -1;
      for (std::size_t k = 0; k < mate.cam_of_shell.size(); ++k)
        if (out.cam_edge[g][mate.cam_of_shell[k]] == j.edge) shell = static_cast<int>(k);
      if (shell < 0) continue;  // a plain revolute or a crease too short: no cam to clear
      const std::vector<Vec2>& section = mate.cam_sections[shell];
      ClearanceCut cut;
      cut.face = f;
      cut.edge = j.edge;
      cut.margin = clearance.margin * s.faces[f].thickness;
      // The mate's section in this face's coordinates at t (the planar relative motion).
      auto posed = [&](double t) {
        const double gamma = j.motion.gamma(t)[0], zl = j.motion.z_left(t)[0], zr = j.motion.z_right(t)[0];
        Vec2 d = Vec2::Zero();
        if (j.motion.d) {
          const VectorJet dj = j.motion.d(t);
          d = Vec2(dj[0][0], dj[1][0]);
        }
        const Eigen::Rotation2Dd r(gamma);
        std::vector<Vec2> q;
        for (const Vec2& x : section)
          q.push_back(this_left ? Vec2(r * (x + Vec2(0, zr)) + d - Vec2(0, zl))
                                : Vec2(r.inverse() * (x + Vec2(0, zl) - d) - Vec2(0, zr)));
        return q;
      };
      // Samples: evenly spaced, each interval halved (at most 10 times) until no section point
      // moves more than half the margin across it, so the grown union covers the motion between.
      std::vector<std::vector<Vec2>> poses;
      std::vector<Vec2> previous;
      double t_prev = 0.0;
      for (int i = 0; i < clearance.samples; ++i) {
        const double t = static_cast<double>(i) / (clearance.samples - 1);
        std::vector<Vec2> q = posed(t);
        if (i > 0) {
          struct Span {
            double t0, t1;
            std::vector<Vec2> q0, q1;
            int depth;
          };
          std::vector<Span> stack{{t_prev, t, previous, q, 0}};
          while (!stack.empty()) {
            Span sp = std::move(stack.back());
            stack.pop_back();
            double step = 0.0;
            for (std::size_t k = 0; k < sp.q0.size(); ++k) step = std::max(step, (sp.q1[k] - sp.q0[k]).norm());
            if (step > cut.margin / 2 && sp.depth < 10) {
              const double tm = 0.5 * (sp.t0 + sp.t1);
              std::vector<Vec2> qm = posed(tm);
              poses.push_back(qm);
              stack.push_back({sp.t0, tm, sp.q0, qm, sp.depth + 1});
              stack.push_back({tm, sp.t1, std::move(qm), sp.q1, sp.depth + 1});
            } else {
              cut.sweep_step = std::max(cut.sweep_step, step);
            }
          }
        }
        poses.push_back(q);
        previous = std::move(q);
        t_prev = t;
      }
      // Union by pairs (a balanced tree: each level halves the count, no ever-growing operand).
      std::vector<BgMulti> level;
      for (const std::vector<Vec2>& q : poses) {
        BgPolygon poly;
        for (const Vec2& x : q) bg::append(poly.outer(), BgPoint(x.x(), x.y()));
        bg::correct(poly);
        level.push_back(BgMulti{poly});
      }
      while (level.size() > 1) {
        std::vector<BgMulti> next_level;
        for (std::size_t k = 0; k + 1 < level.size(); k += 2) {
          BgMulti merged;
          bg::union_(level[k], level[k + 1], merged);
          next_level.push_back(std::move(merged));
        }
        if (level.size() % 2 == 1) next_level.push_back(std::move(level.back()));
        level = std::move(next_level);
      }
      BgMulti swept = std::move(level.front());
      // The union's rings carry every profile sample (thousands of short, nearly collinear
      // segments), on which the round buffer spent minutes (a 4 x 4 Miura: 2 min). Simplified
      // within margin / 4 (Douglas-Peucker: every point of the union stays within that of the
      // simplified ring) and grown by margin + margin / 4, the cut still holds the sweep grown
      // by the margin. An invalid simplification is not used.
      double grow = cut.margin;
      {
        BgMulti simplified;
        bg::simplify(swept, simplified, cut.margin / 4);
        if (bg::is_valid(simplified)) {
          swept = std::move(simplified);
          grow = cut.margin * 1.25;
        }
      }
      BgMulti grown;
      bg::buffer(swept, grown, bg::strategy::buffer::distance_symmetric<double>(grow),
                 bg::strategy::buffer::side_straight(), bg::strategy::buffer::join_round(32),
                 bg::strategy::buffer::end_round(32), bg::strategy::buffer::point_circle(32));
      cut.region_area = bg::area(grown);
      Clearance c;
      c.origin = a;
      c.fold_direction = (b - a).normalized();
      c.x_axis = j.frame.linear().col(0);
      c.w0 = mate.cam_extents[shell][0] - cut.margin;
      c.w1 = mate.cam_extents[shell][1] + cut.margin;
      for (const BgPolygon& poly : grown) {  // outer rings only: a hole in the sweep is cut as well
        std::vector<Vec2> ring;
        for (std::size_t k = 0; k + 1 < poly.outer().size(); ++k) ring.emplace_back(poly.outer()[k].x(), poly.outer()[k].y());
        c.region.push_back(std::move(ring));
      }
      in[f].clearances.push_back(std::move(c));
      out.clearances.push_back(cut);
    }
  }
  build();
  // Which clearances removed material (panel_solid lists the ones whose region missed the slab).
  std::vector<int> next(nf, 0);
  for (ClearanceCut& cut : out.clearances) {
    const int k = next[cut.face]++;
    const auto& unneeded = out.panels[cut.face].clearances_unneeded;
    cut.cut = std::find(unneeded.begin(), unneeded.end(), k) == unneeded.end();
  }
  return out;
}

}  // namespace rigidfold::sorce
