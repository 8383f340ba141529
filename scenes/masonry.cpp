// Columns and running-bond walls (scenes/assemblies.hpp). A wall is built course by course as
// one-dimensional intervals: the course is cut at its joints, openings remove intervals, a
// lintel replaces one, and a remainder too short to be a brick joins its neighbour, so the
// blocks tile the wall minus its openings exactly.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "geometry/polygon.hpp"
#include "laws/restitution.hpp"
#include "scenes/assemblies.hpp"

namespace blockdem::scenes {
namespace {

struct Interval {
    double from_m;
    double to_m;
};

Polygon box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// [from, to) minus the cut intervals, in order.
std::vector<Interval> subtract(Interval whole, std::vector<Interval> cuts) {
    std::sort(cuts.begin(), cuts.end(), [](const Interval& a, const Interval& b) { return a.from_m < b.from_m; });
    std::vector<Interval> out;
    double at = whole.from_m;
    for (const Interval& c : cuts) {
        if (c.from_m > at) out.push_back({at, std::min(c.from_m, whole.to_m)});
        at = std::max(at, c.to_m);
    }
    if (at < whole.to_m) out.push_back({at, whole.to_m});
    std::erase_if(out, [](const Interval& i) { return !(i.to_m > i.from_m); });
    return out;
}

// One stretch of masonry cut at the joints offset + k L; short end pieces join their neighbour.
std::vector<Interval> bricks_in(Interval stretch, double offset_m, double length_m, double min_piece_m) {
    std::vector<double> cuts{stretch.from_m};
    const double tolerance = 1e-9 * length_m;
    for (double k = std::ceil((stretch.from_m - offset_m) / length_m);; k += 1.0) {
        const double x = offset_m + k * length_m;
        if (x >= stretch.to_m - tolerance) break;
        if (x > stretch.from_m + tolerance) cuts.push_back(x);
    }
    cuts.push_back(stretch.to_m);
    if (cuts.size() > 2 && cuts[1] - cuts[0] < min_piece_m) cuts.erase(cuts.begin() + 1);
    if (cuts.size() > 2 && cuts[cuts.size() - 1] - cuts[cuts.size() - 2] < min_piece_m) cuts.erase(cuts.end() - 2);
    std::vector<Interval> out;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) out.push_back({cuts[i], cuts[i + 1]});
    return out;
}

// Whether course r (rows of height h) lies in the opening: its middle is inside the opening.
bool course_in(const WallOpening& o, int r, double h) {
    const double mid = (r + 0.5) * h;
    return mid > o.y_m && mid < o.y_m + o.height_m;
}

bool lintel_course(const WallOpening& o, int r, double h) {
    return o.lintel_bearing_m > 0.0 && course_in(o, r - 1, h) && !course_in(o, r, h);
}

}  // namespace

std::vector<BodyDef> as_bodies(const std::vector<Polygon>& polygons, const BlockStyle& style) {
    std::vector<BodyDef> out;
    out.reserve(polygons.size());
    for (std::size_t i = 0; i < polygons.size(); ++i) {
        BodyDef b;
        b.name = fmt::format("{}{}", style.name_prefix, i);
        b.vertices_m = polygons[i];
        b.material = style.material;
        b.density_kg_m3 = style.density_kg_m3;
        b.thickness_m = style.thickness_m;
        b.record = style.record;
        out.push_back(std::move(b));
    }
    return out;
}

namespace {

// Even-odd rule: a point is inside when a ray to +x crosses the outline an odd number of times.
bool inside(Vec2 p, const Polygon& zone) {
    bool in = false;
    for (std::size_t i = 0, j = zone.size() - 1; i < zone.size(); j = i++) {
        const Vec2 a = zone[i];
        const Vec2 b = zone[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
}

}  // namespace

std::size_t set_kind_inside(std::vector<BodyDef>& bodies, const Polygon& zone, BodyKind kind) {
    std::size_t changed = 0;
    for (BodyDef& b : bodies) {
        Vec2 c;
        for (Vec2 v : b.vertices_m) c += v;
        c = (1.0 / static_cast<double>(b.vertices_m.size())) * c;
        if (!inside(c, zone)) continue;
        b.kind = kind;
        ++changed;
    }
    return changed;
}

std::vector<Polygon> block_column(const std::vector<Vec2>& sizes_m, Vec2 base_center_m) {
    std::vector<Polygon> out;
    double y = base_center_m.y;
    for (const Vec2& s : sizes_m) {
        out.push_back(box(base_center_m.x - 0.5 * s.x, y, base_center_m.x + 0.5 * s.x, y + s.y));
        y += s.y;
    }
    return out;
}

double estimated_block_count(const WallSpec& spec) {
    const double per_course = spec.length_m / spec.brick_length_m + 2.0 + 2.0 * static_cast<double>(spec.openings.size());
    return static_cast<double>(std::max(spec.courses, 0)) * per_course;
}

std::vector<Polygon> masonry_wall(const WallSpec& spec) {
    const double L = spec.brick_length_m;
    const double h = spec.brick_height_m;
    std::vector<Polygon> out;
    for (int r = 0; r < spec.courses; ++r) {
        const bool odd = r % 2 == 1;
        const double offset = odd ? 0.5 * L : 0.0;
        const Interval course = odd && spec.stepped_ends ? Interval{0.5 * L, spec.length_m - 0.5 * L}
                                                        : Interval{0.0, spec.length_m};
        std::vector<Interval> removed;
        std::vector<Interval> lintels;
        for (const WallOpening& o : spec.openings) {
            if (course_in(o, r, h)) removed.push_back({o.x_m, o.x_m + o.width_m});
            if (lintel_course(o, r, h)) {
                const Interval lintel{std::max(course.from_m, o.x_m - o.lintel_bearing_m),
                                      std::min(course.to_m, o.x_m + o.width_m + o.lintel_bearing_m)};
                removed.push_back(lintel);
                lintels.push_back(lintel);
            }
        }
        std::vector<Interval> pieces = lintels;
        for (const Interval& stretch : subtract(course, removed))
            for (const Interval& brick : bricks_in(stretch, offset, L, spec.min_piece_fraction * L)) pieces.push_back(brick);
        std::sort(pieces.begin(), pieces.end(), [](const Interval& a, const Interval& b) { return a.from_m < b.from_m; });
        const double y0 = spec.origin_m.y + r * h;
        for (const Interval& p : pieces)
            out.push_back(box(spec.origin_m.x + p.from_m, y0, spec.origin_m.x + p.to_m, y0 + h));
    }
    return out;
}

Model s3_wall_scene(int bricks, double duration_s, double dt_s) {
    constexpr double brick_length = 0.2;
    constexpr double brick_height = 0.1;
    Model m;
    m.settings.duration_s = duration_s;
    m.settings.dt_s = dt_s;
    m.settings.gravity_m_s2 = 9.81;  // as the peers (scen.h)
    m.contact = MaterialPairs::uniform(
        {.kn_N_m = 6e7, .ks_N_m = 6e7, .mu = 0.6, .h_n = damping_ratio_rebound(0.5), .h_s = 0.2});
    m.table_motion.horizontal = SineMotion{0.3 * 9.81, 0.5, 0.0, 0.0, 0.0};

    const int columns = std::max(2, static_cast<int>(std::lround(std::sqrt(2.0 * bricks))));
    BodyDef table;
    table.name = "table";
    table.kind = BodyKind::driven;
    table.vertices_m = box(-0.5, -0.2, columns * brick_length + 0.5, 0.0);
    table.density_kg_m3 = 1000.0;
    m.bodies.push_back(table);
    int made = 0;
    for (int r = 0; made < bricks; ++r) {
        const int in_row = r % 2 == 0 ? columns : columns - 1;
        const double x0 = r % 2 == 0 ? 0.0 : 0.5 * brick_length;
        for (int j = 0; j < in_row && made < bricks; ++j, ++made) {
            BodyDef b;
            b.name = fmt::format("brick{}", made);
            b.vertices_m = box(x0 + j * brick_length, r * brick_height, x0 + (j + 1) * brick_length, (r + 1) * brick_height);
            b.mass_kg = 40.0;
            b.record = false;
            m.bodies.push_back(std::move(b));
        }
    }
    return m;
}

Polygon keyed_brick(Vec2 origin_m, double length_m, double height_m, double key_width_m, double key_depth_m) {
    const double x = origin_m.x, y = origin_m.y, L = length_m, H = height_m, w = 0.5 * key_width_m, t = key_depth_m;
    const double c1 = x + 0.25 * L, c2 = x + 0.75 * L;
    return {// the bottom, left to right, with the two grooves cut up into the brick
            {x, y}, {c1 - w, y}, {c1 - w, y + t}, {c1 + w, y + t}, {c1 + w, y}, {c2 - w, y}, {c2 - w, y + t},
            {c2 + w, y + t}, {c2 + w, y}, {x + L, y},
            // the top, right to left, with the two tongues standing on it
            {x + L, y + H}, {c2 + w, y + H}, {c2 + w, y + H + t}, {c2 - w, y + H + t}, {c2 - w, y + H}, {c1 + w, y + H},
            {c1 + w, y + H + t}, {c1 - w, y + H + t}, {c1 - w, y + H}, {x, y + H}};
}

Model keyed_wall_scene(int bricks, double duration_s) {
    constexpr double brick_length = 0.2;
    constexpr double brick_height = 0.1;
    Model m = s3_wall_scene(0, duration_s);  // the table, the motion and the contact of S3
    m.settings.dt_s.reset();
    const int columns = std::max(2, static_cast<int>(std::lround(std::sqrt(2.0 * bricks))));
    m.bodies.front().vertices_m = box(-0.5, -0.2, columns * brick_length + 0.5, 0.0);
    int made = 0;
    for (int r = 0; made < bricks; ++r) {
        const int in_row = r % 2 == 0 ? columns : columns - 1;
        const double x0 = r % 2 == 0 ? 0.0 : 0.5 * brick_length;
        for (int j = 0; j < in_row && made < bricks; ++j, ++made) {
            BodyDef b;
            b.name = fmt::format("brick{}", made);
            b.vertices_m = keyed_brick({x0 + j * brick_length, r * brick_height}, brick_length, brick_height, 0.04, 0.02);
            b.mass_kg = 40.0;
            b.record = false;
            m.bodies.push_back(std::move(b));
        }
    }
    return m;
}

Model bonded_wall_scene(int bricks, double duration_s) {
    Model m = s3_wall_scene(bricks, duration_s);
    ContactParameters joint = m.contact.at(0, 0);
    joint.stiffness = StiffnessBasis::per_length;
    joint.kn_pa_m = joint.kn_N_m / 0.05;  // S3's point stiffness for 0.05 m x 1 m of joint
    joint.ks_pa_m = joint.ks_N_m / 0.05;
    joint.cohesion_pa = 2e5;
    joint.tensile_strength_pa = 1e5;
    m.contact = MaterialPairs::uniform(joint);
    for (std::size_t i = 1; i < m.bodies.size(); ++i) m.bodies[i].bond_group = 1;  // bodies[0] is the table
    return m;
}

}  // namespace blockdem::scenes
