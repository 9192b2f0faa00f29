// Planarium's OMPL harness: the suite's problems planned by OMPL's own RRT, RRT-Connect and RRT*, so that
// the benchmark suite (scripts/bench.mjs) measures OMPL beside Planarium on this machine, seed by
// seed. Built by the suite with g++ -O3 against OMPL 1.5 (Debian's libompl-dev) when it is there.
//
//   harness PROBLEM PLANNER FIRST_SEED LAST_SEED TIME_LIMIT_S [--paths]
//
// PROBLEM is a problem file that scripts/ompl.mjs writes from a scenario (whitespace-separated
// tokens, see read_problem). PLANNER is rrt, rrt-connect or rrt-star (path length, improving until
// TIME_LIMIT_S: its cost is the best path's when the time is up). One JSON line per seed on stdout:
// {"seed":1,"planner":"rrt","solved":true,"time_ms":0.61,"checks":8400,"nodes":120,"deadline":false,"cost":1.62}
// (deadline: the time limit was reached inside a motion check; see Checker).
// time_ms is the planner's solve() alone (set-up excluded); checks counts every call of the state
// validity checker during solve(); nodes the vertices of the planner's data (both trees); cost the
// solution path's length in the space's metric (-1 unsolved). With --paths, a solved seed's line also
// has "path": the solution's states, as OMPL returns them.
//
// The set-up is Planarium's for the same scenario: the bounds, the obstacles (closed sets: touching
// is a collision; exact tests), the robot (a point, a rigid polygon, or a planar chain whose joints
// all wrap), the metric (Euclidean; translation + w·|Δθ|; the chain's sum of link-end travels), the
// motion resolution (each motion is checked at ceil(distance / resolution) segments, in the metric),
// range, goal bias and goal tolerance.

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/base/PlannerData.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ob = ompl::base;
namespace og = ompl::geometric;

struct Pt {
  double x, y;
};

struct Shape {
  std::vector<Pt> pts;  // a closed polygon (3 or more points) or a segment (2 points)
  double x0, y0, x1, y1;  // its bounding box
};

struct Problem {
  std::string robot;  // point, rigid, chain
  double bounds[4] = {0, 0, 1, 1};
  double resolution = 0.001, range = 0, goal_bias = 0.05, goal_tolerance = 0;
  std::vector<double> start, goal;
  std::vector<Pt> footprint;  // rigid
  double rotation_weight = 0;  // rigid
  std::vector<double> links;  // chain
  Pt base{0, 0};  // chain
  double tip = 0;  // chain
  bool self_collision = true;  // chain
  std::vector<Shape> obstacles;
};

static void fail(const std::string &what) {
  throw std::runtime_error(what);
}

// The problem file: keywords followed by their values.
//   robot point|rigid|chain  bounds x0 y0 x1 y1  resolution r  range r  goal_bias g
//   goal_tolerance t  start n v..  goal n v..  footprint n x y ..  rotation_weight w
//   base x y  links n l..  tip t  self_collision 0|1  polygon n x y ..  segment x0 y0 x1 y1
static Problem read_problem(const char *path) {
  std::ifstream in(path);
  if (!in) fail(std::string("cannot read ") + path);
  Problem p;
  std::string key;
  auto num = [&](const char *what) {
    double v;
    if (!(in >> v)) fail(std::string("problem file: a number expected after ") + what);
    return v;
  };
  auto count = [&](const char *what) {
    double v = num(what);
    if (v < 0 || v > 100000 || v != std::floor(v)) fail(std::string("problem file: bad count after ") + what);
    return static_cast<size_t>(v);
  };
  auto points = [&](const char *what) {
    std::vector<Pt> pts(count(what));
    for (auto &q : pts) {
      q.x = num(what);
      q.y = num(what);
    }
    return pts;
  };
  auto shape = [&](std::vector<Pt> pts) {
    Shape s{pts, 1e300, 1e300, -1e300, -1e300};
    for (auto &q : pts) {
      s.x0 = std::min(s.x0, q.x);
      s.y0 = std::min(s.y0, q.y);
      s.x1 = std::max(s.x1, q.x);
      s.y1 = std::max(s.y1, q.y);
    }
    p.obstacles.push_back(s);
  };
  while (in >> key) {
    if (key == "robot") in >> p.robot;
    else if (key == "bounds") for (double &b : p.bounds) b = num("bounds");
    else if (key == "resolution") p.resolution = num("resolution");
    else if (key == "range") p.range = num("range");
    else if (key == "goal_bias") p.goal_bias = num("goal_bias");
    else if (key == "goal_tolerance") p.goal_tolerance = num("goal_tolerance");
    else if (key == "start" || key == "goal") {
      std::vector<double> v(count(key.c_str()));
      for (double &x : v) x = num(key.c_str());
      (key == "start" ? p.start : p.goal) = v;
    } else if (key == "footprint") p.footprint = points("footprint");
    else if (key == "rotation_weight") p.rotation_weight = num("rotation_weight");
    else if (key == "base") p.base = {num("base"), num("base")};
    else if (key == "links") {
      p.links.resize(count("links"));
      for (double &l : p.links) l = num("links");
    } else if (key == "tip") p.tip = num("tip");
    else if (key == "self_collision") p.self_collision = num("self_collision") != 0;
    else if (key == "polygon") {
      auto pts = points("polygon");
      if (pts.size() < 3) fail("problem file: a polygon needs 3 points");
      shape(pts);
    } else if (key == "segment") {
      Pt a{num("segment"), num("segment")}, b{num("segment"), num("segment")};
      shape({a, b});
    } else fail("problem file: unknown keyword " + key);
  }
  if (p.robot != "point" && p.robot != "rigid" && p.robot != "chain") fail("problem file: robot must be point, rigid or chain");
  if (!(p.resolution > 0)) fail("problem file: resolution must be positive");
  return p;
}

// Exact predicates on closed sets (touching counts as meeting).
static double cross(Pt o, Pt a, Pt b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
static bool on_segment(Pt a, Pt b, Pt q) {
  return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y);
}
static int sign(double v) {
  return (v > 0) - (v < 0);
}
static bool segments_meet(Pt a, Pt b, Pt c, Pt d) {
  int d1 = sign(cross(c, d, a)), d2 = sign(cross(c, d, b)), d3 = sign(cross(a, b, c)), d4 = sign(cross(a, b, d));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && on_segment(c, d, a)) || (d2 == 0 && on_segment(c, d, b)) || (d3 == 0 && on_segment(a, b, c)) ||
         (d4 == 0 && on_segment(a, b, d));
}
// Point in a closed polygon (its boundary included), either winding.
static bool in_polygon(const std::vector<Pt> &poly, Pt q) {
  bool inside = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    Pt a = poly[j], b = poly[i];
    if (cross(a, b, q) == 0 && on_segment(a, b, q)) return true;
    if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
  }
  return inside;
}
static bool segment_meets(const Shape &s, Pt a, Pt b) {
  if (std::max(a.x, b.x) < s.x0 || std::min(a.x, b.x) > s.x1 || std::max(a.y, b.y) < s.y0 || std::min(a.y, b.y) > s.y1) return false;
  size_t n = s.pts.size();
  if (n == 2) return segments_meet(a, b, s.pts[0], s.pts[1]);
  for (size_t i = 0, j = n - 1; i < n; j = i++)
    if (segments_meet(a, b, s.pts[j], s.pts[i])) return true;
  return in_polygon(s.pts, a);
}
// A closed polygon (the robot) meets a shape: edges cross, or one lies inside the other.
static bool polygon_meets(const std::vector<Pt> &poly, double bx0, double by0, double bx1, double by1, const Shape &s) {
  if (bx1 < s.x0 || bx0 > s.x1 || by1 < s.y0 || by0 > s.y1) return false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if (segment_meets(s, poly[j], poly[i])) return true;
  return in_polygon(poly, s.pts[0]);
}

// A compound space whose motions are checked in its own metric: ceil(distance / resolution)
// segments, as Planarium does (OMPL's compound default takes the largest count of its parts, each
// at the fraction of its own extent, which for SE(2) is about twice as fine).
class MetricSpace : public ob::CompoundStateSpace {
 public:
  unsigned int validSegmentCount(const ob::State *a, const ob::State *b) const override {
    return ob::StateSpace::validSegmentCount(a, b);
  }
};

// Translation + w·|Δθ| (OMPL's SE(2) with rotation weight w).
class PlaneSpace : public MetricSpace {
 public:
  PlaneSpace(const double *bounds, double w) {
    auto r2 = std::make_shared<ob::RealVectorStateSpace>(2);
    ob::RealVectorBounds b(2);
    b.setLow(0, bounds[0]);
    b.setLow(1, bounds[1]);
    b.setHigh(0, bounds[2]);
    b.setHigh(1, bounds[3]);
    r2->setBounds(b);
    addSubspace(r2, 1.0);
    addSubspace(std::make_shared<ob::SO2StateSpace>(), w);
    lock();
  }
};

// Joints that all wrap; the distance is the sum over links of how far each link's end moves.
class ChainSpace : public MetricSpace {
 public:
  explicit ChainSpace(const std::vector<double> &links) : links_(links) {
    for (size_t i = 0; i < links.size(); ++i) addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
    lock();
  }
  double distance(const ob::State *a, const ob::State *b) const override {
    const auto *ca = a->as<ob::CompoundState>(), *cb = b->as<ob::CompoundState>();
    double ta = 0, tb = 0, dx = 0, dy = 0, d = 0;
    for (size_t i = 0; i < links_.size(); ++i) {
      ta += ca->as<ob::SO2StateSpace::StateType>(i)->value;
      tb += cb->as<ob::SO2StateSpace::StateType>(i)->value;
      dx += links_[i] * (std::cos(ta) - std::cos(tb));
      dy += links_[i] * (std::sin(ta) - std::sin(tb));
      d += std::sqrt(dx * dx + dy * dy);
    }
    return d;
  }
  // Planarium's extent of this metric: every link end travels at most twice its reach (so that
  // OMPL's default range, 0.2 of it, is Planarium's).
  double getMaximumExtent() const override {
    double reach = 0, sum = 0;
    for (double l : links_) sum += 2 * (reach += l);
    return sum;
  }

 private:
  std::vector<double> links_;
};

class Checker : public ob::StateValidityChecker {
 public:
  Checker(const ob::SpaceInformationPtr &si, const Problem &p) : ob::StateValidityChecker(si), p_(p) {}
  mutable unsigned long long checks = 0;
  // Past the deadline every state is invalid, as in Planarium: OMPL's RRT-Connect checks its
  // termination condition between iterations only, and its CONNECT loop can go on for ever when
  // the step toward the target does not bring the nearest node closer in the metric (the chain's,
  // whose distance is not monotone along a joint-space line); refusing every motion ends it.
  std::chrono::steady_clock::time_point deadline;
  mutable bool expired = false;

  bool isValid(const ob::State *state) const override {
    ++checks;
    if (expired || ((checks & 255) == 0 && std::chrono::steady_clock::now() > deadline)) return !(expired = true);
    const Problem &p = p_;
    if (p.robot == "point") {
      const auto *s = state->as<ob::RealVectorStateSpace::StateType>();
      Pt q{s->values[0], s->values[1]};
      if (!inside(q)) return false;
      for (const auto &o : p.obstacles) {
        if (q.x < o.x0 || q.x > o.x1 || q.y < o.y0 || q.y > o.y1) continue;
        if (o.pts.size() == 2 ? (cross(o.pts[0], o.pts[1], q) == 0 && on_segment(o.pts[0], o.pts[1], q)) : in_polygon(o.pts, q))
          return false;
      }
      return true;
    }
    const auto *c = state->as<ob::CompoundState>();
    if (p.robot == "rigid") {
      const auto *xy = c->as<ob::RealVectorStateSpace::StateType>(0);
      double th = c->as<ob::SO2StateSpace::StateType>(1)->value, cs = std::cos(th), sn = std::sin(th);
      Pt o{xy->values[0], xy->values[1]};
      if (!inside(o)) return false;
      body_.resize(p.footprint.size());
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      for (size_t i = 0; i < body_.size(); ++i) {
        Pt f = p.footprint[i];
        body_[i] = {o.x + cs * f.x - sn * f.y, o.y + sn * f.x + cs * f.y};
        x0 = std::min(x0, body_[i].x), y0 = std::min(y0, body_[i].y);
        x1 = std::max(x1, body_[i].x), y1 = std::max(y1, body_[i].y);
      }
      for (const auto &s : p.obstacles)
        if (polygon_meets(body_, x0, y0, x1, y1, s)) return false;
      return true;
    }
    // The chain: joint points from the base, then the tip; every point in bounds.
    size_t n = p.links.size();
    body_.assign(1, p.base);
    double th = 0;
    for (size_t i = 0; i <= n; ++i) {
      if (i == n && !(p.tip > 0)) break;
      if (i < n) th += c->as<ob::SO2StateSpace::StateType>(i)->value;
      double l = i < n ? p.links[i] : p.tip;
      body_.push_back({body_.back().x + l * std::cos(th), body_.back().y + l * std::sin(th)});
    }
    for (const Pt &q : body_)
      if (!inside(q)) return false;
    size_t segs = body_.size() - 1;
    for (size_t k = 0; k < segs; ++k)
      for (const auto &s : p.obstacles)
        if (segment_meets(s, body_[k], body_[k + 1])) return false;
    if (p.self_collision) {
      // Adjacent links fold when the joint between them turns by ±π; others may not meet.
      for (size_t i = 1; i < n; ++i)
        if (std::abs(M_PI - std::abs(c->as<ob::SO2StateSpace::StateType>(i)->value)) < 1e-9) return false;
      for (size_t i = 0; i < segs; ++i)
        for (size_t j = i + 2; j < segs; ++j)
          if (segments_meet(body_[i], body_[i + 1], body_[j], body_[j + 1])) return false;
    }
    return true;
  }

 private:
  bool inside(Pt q) const {
    return q.x >= p_.bounds[0] && q.x <= p_.bounds[2] && q.y >= p_.bounds[1] && q.y <= p_.bounds[3];
  }
  const Problem &p_;
  mutable std::vector<Pt> body_;
};

static ob::StateSpacePtr make_space(const Problem &p) {
  if (p.robot == "point") {
    auto s = std::make_shared<ob::RealVectorStateSpace>(2);
    ob::RealVectorBounds b(2);
    b.setLow(0, p.bounds[0]);
    b.setLow(1, p.bounds[1]);
    b.setHigh(0, p.bounds[2]);
    b.setHigh(1, p.bounds[3]);
    s->setBounds(b);
    return s;
  }
  if (p.robot == "rigid") return std::make_shared<PlaneSpace>(p.bounds, p.rotation_weight);
  return std::make_shared<ChainSpace>(p.links);
}

static void set_state(const ob::StateSpacePtr &space, ob::ScopedState<> &st, const std::vector<double> &v, const char *what) {
  if (v.size() != space->getDimension()) fail(std::string("problem file: ") + what + " has the wrong dimension");
  space->copyFromReals(st.get(), v);
}

// One run: everything built after the seed is set, so that each seed's run is reproducible.
static void run(const Problem &p, const std::string &planner, unsigned seed, double limit, bool paths) {
  ompl::RNG::setSeed(seed);
  auto space = make_space(p);
  space->setup();
  space->setLongestValidSegmentFraction(p.resolution / space->getMaximumExtent());
  og::SimpleSetup ss(space);
  auto checker = std::make_shared<Checker>(ss.getSpaceInformation(), p);
  ss.setStateValidityChecker(checker);
  ob::ScopedState<> start(space), goal(space);
  set_state(space, start, p.start, "start");
  set_state(space, goal, p.goal, "goal");
  ss.setStartAndGoalStates(start, goal, std::max(p.goal_tolerance, std::numeric_limits<double>::epsilon()));
  if (planner == "rrt") {
    auto rrt = std::make_shared<og::RRT>(ss.getSpaceInformation());
    if (p.range > 0) rrt->setRange(p.range);
    rrt->setGoalBias(p.goal_bias);
    ss.setPlanner(rrt);
  } else if (planner == "rrt-connect") {
    auto rc = std::make_shared<og::RRTConnect>(ss.getSpaceInformation());
    if (p.range > 0) rc->setRange(p.range);
    ss.setPlanner(rc);
  } else if (planner == "rrt-star") {
    // Path length, with a threshold no path meets: RRT* improves until the time limit (as
    // Planarium's with improve_for past what the limit allows), and the cost is the best path's.
    auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(ss.getSpaceInformation());
    objective->setCostThreshold(ob::Cost(0.0));
    ss.setOptimizationObjective(objective);
    auto rs = std::make_shared<og::RRTstar>(ss.getSpaceInformation());
    if (p.range > 0) rs->setRange(p.range);
    rs->setGoalBias(p.goal_bias);
    ss.setPlanner(rs);
  } else {
    fail("planner must be rrt, rrt-connect or rrt-star, not " + planner);
  }
  ss.setup();
  checker->checks = 0;
  auto t0 = std::chrono::steady_clock::now();
  checker->deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(limit));
  ob::PlannerStatus status = ss.getPlanner()->solve(ob::timedPlannerTerminationCondition(limit));
  auto t1 = std::chrono::steady_clock::now();
  unsigned long long checks = checker->checks;
  ob::PlannerData data(ss.getSpaceInformation());
  ss.getPlanner()->getPlannerData(data);
  bool solved = status == ob::PlannerStatus::EXACT_SOLUTION;
  double ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  // The solution's length in the space's metric (the planner's path as returned, not simplified).
  double cost = solved ? ss.getSolutionPath().length() : -1.0;
  std::printf("{\"seed\":%u,\"planner\":\"%s\",\"solved\":%s,\"time_ms\":%.6f,\"checks\":%llu,\"nodes\":%u,\"deadline\":%s,\"cost\":%.17g", seed,
              planner.c_str(), solved ? "true" : "false", ms, checks, data.numVertices(), checker->expired ? "true" : "false", cost);
  // With paths: the solution's states as OMPL returns them (in the problem file's coordinates), so
  // that Planarium's motion validator can judge OMPL's paths by its own rule (scripts/ompl-paths.mjs).
  if (paths && solved) {
    std::printf(",\"path\":[");
    const auto &states = ss.getSolutionPath().getStates();
    for (std::size_t i = 0; i < states.size(); ++i) {
      std::vector<double> v;
      space->copyToReals(v, states[i]);
      std::printf(i ? ",[" : "[");
      for (std::size_t k = 0; k < v.size(); ++k) std::printf(k ? ",%.17g" : "%.17g", v[k]);
      std::printf("]");
    }
    std::printf("]");
  }
  std::printf("}\n");
  std::fflush(stdout);
}

int main(int argc, char **argv) {
  bool paths = argc == 7 && std::string(argv[6]) == "--paths";
  if (argc != 6 && !paths) {
    std::fprintf(stderr, "usage: %s PROBLEM PLANNER FIRST_SEED LAST_SEED TIME_LIMIT_S [--paths]\n", argv[0]);
    return 2;
  }
  try {
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    Problem p = read_problem(argv[1]);
    long first = std::stol(argv[3]), last = std::stol(argv[4]);
    double limit = std::stod(argv[5]);
    if (first < 1 || last < first || last - first > 100000) fail("seeds: FIRST_SEED 1 or more, LAST_SEED at least FIRST_SEED");
    if (!(limit > 0 && limit <= 3600)) fail("TIME_LIMIT_S must be in (0, 3600]");
    for (long s = first; s <= last; ++s) run(p, argv[2], static_cast<unsigned>(s), limit, paths);
  } catch (const std::exception &e) {
    std::fprintf(stderr, "harness: %s\n", e.what());
    return 1;
  }
  return 0;
}
