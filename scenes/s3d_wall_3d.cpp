#include "scenes/s3d_wall_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "world/step_3d.hpp"

namespace blockdem::scenes {
namespace {

// One course of the wall: its bricks in each wythe and the x of its first centre [m].
struct Course {
    std::array<int, 2> count{0, 0};
    double first_x_m = 0.0;
};

// S3D's courses: C bricks a wythe in even courses, C - 1 shifted by half a pitch in odd ones,
// filled course by course, wythe 0 then wythe 1, until there are N.
std::vector<Course> s3d_courses(const S3dWallDef& def, int per_course) {
    const double pitch_m = def.brick_m.x + def.gap_m;
    std::vector<Course> courses;
    for (int placed = 0, course = 0; placed < def.bricks; ++course) {
        const bool odd = course % 2 == 1;
        Course c;
        c.first_x_m = odd ? pitch_m : 0.5 * pitch_m;
        for (int wythe = 0; wythe < 2; ++wythe) {
            c.count[wythe] = std::min(odd ? per_course - 1 : per_course, def.bricks - placed);
            placed += c.count[wythe];
        }
        courses.push_back(c);
    }
    return courses;
}

// The brick pairs of one wythe that share a bed joint between course `lower` and the one above
// (bricks whose spans along x overlap).
int bed_pairs(const Course& lower, const Course& upper, int wythe, double pitch_m, double length_m) {
    int pairs = 0;
    for (int k = 0; k < upper.count[wythe]; ++k) {
        const double x_m = upper.first_x_m + pitch_m * k;
        const auto first = static_cast<int>(std::ceil((x_m - length_m - lower.first_x_m) / pitch_m));
        for (int j = std::max(first, 0); j < lower.count[wythe]; ++j) {
            const double gap_x_m = std::abs(lower.first_x_m + pitch_m * j - x_m);
            if (gap_x_m >= length_m) break;
            ++pairs;
        }
    }
    return pairs;
}

// How far each course of each wythe sinks [m] under the weight above it, at the springs' static
// compression: a bed joint of p brick pairs carries the bricks above it on 4 p points of kn each
// (a face patch's corner shares sum to 4, geometry/corner_share_3d.hpp), so it closes by
// m g (bricks above) / (4 kn p), and a course sinks by the sum of the joints below it.
// Why. Placed touching, as S3D places them, the bricks fall together and the wall's compression
// climbs from the base one course in about 0.7 ms (7 steps at 1e-4 s, with kn lowered to 1e6 N/m
// a point): 100 settling steps left the upper two thirds of a 1e4-brick wall falling, its bed joints
// not yet contacts, where S3D times a wall whose every bed joint carries its load (the peers' own
// settling, shared/peers/three_d/README.md). Placed at their static compression, the courses carry
// their load from the first step, and the settling steps only take out the joints' differences
// from the mean (end bricks on one support, the running bond's unequal shares).
std::vector<std::array<double, 2>> course_sinking_m(const S3dWallDef& def, const std::vector<Course>& courses) {
    const Vec3 b = def.brick_m;
    const double pitch_m = b.x + def.gap_m;
    const double brick_weight_n = def.density_kg_m3 * b.x * b.y * b.z * World3d{}.gravity_m_s2;
    std::vector<std::array<double, 2>> sinking(courses.size(), {0.0, 0.0});
    for (int wythe = 0; wythe < 2; ++wythe) {
        int above = 0;
        for (const Course& c : courses) above += c.count[wythe];
        double sunk_m = 0.0;
        for (std::size_t c = 0; c < courses.size(); ++c) {
            // The bottom course stands on the base, one pair a brick.
            const int pairs = c == 0 ? courses[0].count[wythe]
                                     : bed_pairs(courses[c - 1], courses[c], wythe, pitch_m, b.x);
            if (pairs > 0) sunk_m += brick_weight_n * above / (4.0 * def.contact.kn_N_m * pairs);
            sinking[c][wythe] = sunk_m;
            above -= courses[c].count[wythe];
        }
    }
    return sinking;
}

}  // namespace

std::vector<Vec3> s3d_brick_centres(const S3dWallDef& def, int& per_course) {
    const Vec3 b = def.brick_m;
    per_course = std::max(2, static_cast<int>(std::lround(std::sqrt(static_cast<double>(def.bricks)))));
    const double pitch_m = b.x + def.gap_m;
    const std::vector<Course> courses = s3d_courses(def, per_course);
    const std::vector<std::array<double, 2>> sinking_m = course_sinking_m(def, courses);
    std::vector<Vec3> centres;
    centres.reserve(static_cast<std::size_t>(def.bricks));
    for (std::size_t course = 0; course < courses.size(); ++course) {
        const Course& c = courses[course];
        for (int wythe = 0; wythe < 2; ++wythe) {
            const double y_m = (wythe == 0 ? -0.5 : 0.5) * (b.y + def.gap_m);
            const double z_m = 0.5 * b.z + b.z * static_cast<double>(course) - sinking_m[course][wythe];
            for (int k = 0; k < c.count[wythe]; ++k) centres.push_back({c.first_x_m + pitch_m * k, y_m, z_m});
        }
    }
    return centres;
}
World3d s3d_wall_3d(const S3dWallDef& def) {
    World3d w;
    w.contact = def.contact;
    w.table.y = SineMotion{def.amplitude_m_s2, def.period_s, 0.0, def.settling_steps * def.dt_s, 0.0};
    w.dt_s = def.dt_s;
    int per_course = 0;
    const std::vector<Vec3> centres = s3d_brick_centres(def, per_course);
    // S3D's base: (C pitch + 1) x 2 x 0.5 m, top at z = 0, 0.5 m beyond the wall's ends.
    const double length_m = per_course * (def.brick_m.x + def.gap_m) + 1.0;
    add_body(w,
             make_rigid_body_3d("base", box_vertices({length_m, 2.0, 0.5}, {0.5 * (length_m - 1.0), 0.0, -0.25}),
                                def.density_kg_m3),
             BodyKind3d::driven);
    // One brick's hull, then moved: the bricks share its shape.
    const RigidBody3d brick = make_rigid_body_3d("brick", box_vertices(def.brick_m, {}), def.density_kg_m3);
    for (std::size_t i = 0; i < centres.size(); ++i) {
        RigidBody3d r = brick;
        r.name = fmt::format("brick_{}", i);
        r.position_m = centres[i];
        add_body(w, std::move(r), BodyKind3d::dynamic);
    }
    return w;
}

World3d settled_s3d_wall_3d(const S3dWallDef& def) {
    World3d w = s3d_wall_3d(def);
    for (int i = 0; i < def.settling_steps; ++i) step_3d(w);
    return w;
}

}  // namespace blockdem::scenes
