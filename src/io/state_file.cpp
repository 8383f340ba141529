#include "io/state_file.hpp"

#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <system_error>

#include <fmt/format.h>

#include "dynamics/highest_mode.hpp"
#include "io/external_loads_state.hpp"
#include "io/input_error.hpp"
#include "io/output_file.hpp"

namespace blockdem {
namespace {

constexpr const char* format_name = "blockdem state";
constexpr std::int64_t format_version = 1;

// HDF5 prints its own error stack to stderr by default; the messages here say it better.
void quiet_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// Closes an HDF5 handle at the end of a scope.
class Handle {
public:
    Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
    ~Handle() {
        if (id_ >= 0) close_(id_);
    }
    Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle& operator=(Handle&&) = delete;
    hid_t get() const { return id_; }
    bool ok() const { return id_ >= 0; }

private:
    hid_t id_;
    herr_t (*close_)(hid_t);
};

Handle string_type() {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), H5T_VARIABLE);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
    return type;
}

template <class T>
hid_t memory_type();
template <>
hid_t memory_type<double>() { return H5T_NATIVE_DOUBLE; }
template <>
hid_t memory_type<std::int64_t>() { return H5T_NATIVE_INT64; }
template <>
hid_t memory_type<std::uint32_t>() { return H5T_NATIVE_UINT32; }
template <>
hid_t memory_type<std::uint8_t>() { return H5T_NATIVE_UINT8; }

}  // namespace

StateGroup::StateGroup(std::int64_t id, std::string file, std::string path)
    : id_(id), file_(std::move(file)), path_(std::move(path)) {}

StateGroup::~StateGroup() {
    if (id_ < 0) return;
    if (H5Iget_type(id_) == H5I_FILE)
        H5Fclose(id_);
    else
        H5Gclose(id_);
}

StateGroup::StateGroup(StateGroup&& other) noexcept : id_(other.id_), file_(std::move(other.file_)), path_(std::move(other.path_)) {
    other.id_ = -1;
}

void StateGroup::fail_read(const std::string& name, const std::string& problem) const {
    const std::string item = path_ == "/" ? "/" + name : path_ + "/" + name;
    throw InputError({file_, "", 0, 0}, fmt::format("not a readable blockdem state file: {}: {}", item, problem));
}

void StateGroup::fail_write(const std::string& name) const {
    throw OutputError(fmt::format("{}: cannot write {}/{} of the state (disk full?)", file_, path_ == "/" ? "" : path_, name));
}

StateGroup StateGroup::create_group(const std::string& name) {
    const hid_t g = H5Gcreate2(id_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (g < 0) fail_write(name);
    return StateGroup(g, file_, path_ == "/" ? "/" + name : path_ + "/" + name);
}

StateGroup StateGroup::open_group(const std::string& name) const {
    if (!has(name)) fail_read(name, "missing group");
    const hid_t g = H5Gopen2(id_, name.c_str(), H5P_DEFAULT);
    if (g < 0) fail_read(name, "cannot open the group");
    return StateGroup(g, file_, path_ == "/" ? "/" + name : path_ + "/" + name);
}

bool StateGroup::has(const std::string& name) const {
    return H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0 || H5Aexists(id_, name.c_str()) > 0;
}

namespace {

// A dataset of the given shape from contiguous memory.
bool write_array(hid_t loc, const std::string& name, hid_t type, const void* data, const std::vector<hsize_t>& dims) {
    Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
    if (!space.ok()) return false;
    Handle set(H5Dcreate2(loc, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    if (!set.ok()) return false;
    hsize_t count = 1;
    for (hsize_t d : dims) count *= d;
    return count == 0 || H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0;
}

// n items as n rows, or as n / slots rows of `slots` (per contact point), then the item's own
// dimensions (2 for a Vec2).
std::vector<hsize_t> shape_of(std::size_t items, std::size_t slots, std::vector<hsize_t> item) {
    std::vector<hsize_t> dims;
    if (slots > 0) dims = {items / slots, slots};
    else dims = {items};
    dims.insert(dims.end(), item.begin(), item.end());
    return dims;
}

}  // namespace

void StateGroup::write(const std::string& name, const std::vector<double>& v, std::size_t slots) {
    if (!write_array(id_, name, H5T_NATIVE_DOUBLE, v.data(), shape_of(v.size(), slots, {}))) fail_write(name);
}
void StateGroup::write(const std::string& name, const std::vector<std::int64_t>& v, std::size_t slots) {
    if (!write_array(id_, name, H5T_NATIVE_INT64, v.data(), shape_of(v.size(), slots, {}))) fail_write(name);
}
void StateGroup::write(const std::string& name, const std::vector<std::uint32_t>& v, std::size_t slots) {
    if (!write_array(id_, name, H5T_NATIVE_UINT32, v.data(), shape_of(v.size(), slots, {}))) fail_write(name);
}
void StateGroup::write(const std::string& name, const std::vector<std::uint8_t>& v, std::size_t slots) {
    if (!write_array(id_, name, H5T_NATIVE_UINT8, v.data(), shape_of(v.size(), slots, {}))) fail_write(name);
}
void StateGroup::write(const std::string& name, const std::vector<Vec2>& v, std::size_t slots) {
    std::vector<double> flat;
    flat.reserve(2 * v.size());
    for (Vec2 p : v) {
        flat.push_back(p.x);
        flat.push_back(p.y);
    }
    if (!write_array(id_, name, H5T_NATIVE_DOUBLE, flat.data(), shape_of(v.size(), slots, {2}))) fail_write(name);
}
void StateGroup::write(const std::string& name, const std::vector<std::string>& v) {
    std::vector<const char*> pointers;
    for (const std::string& s : v) pointers.push_back(s.c_str());
    const Handle type = string_type();
    if (!write_array(id_, name, type.get(), pointers.data(), {v.size()})) fail_write(name);
}

namespace {

bool write_attribute(hid_t loc, const std::string& name, hid_t type, const void* value) {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle attribute(H5Acreate2(loc, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    return attribute.ok() && H5Awrite(attribute.get(), type, value) >= 0;
}

}  // namespace

void StateGroup::set(const std::string& name, double value) {
    if (!write_attribute(id_, name, H5T_NATIVE_DOUBLE, &value)) fail_write(name);
}
void StateGroup::set(const std::string& name, std::int64_t value) {
    if (!write_attribute(id_, name, H5T_NATIVE_INT64, &value)) fail_write(name);
}
void StateGroup::set(const std::string& name, const std::string& value) {
    const char* text = value.c_str();
    const Handle type = string_type();
    if (!write_attribute(id_, name, type.get(), &text)) fail_write(name);
}

namespace {

}  // namespace

// Reads a numeric dataset of shape (rows, trailing...) into out; expected_rows < 0: any.
template <class T>
static void read_numeric(const StateGroup& g, hid_t loc, const std::string& name, const std::vector<hsize_t>& trailing,
                         std::int64_t expected_rows, std::vector<T>& out,
                         void (StateGroup::*fail)(const std::string&, const std::string&) const) {
    if (H5Lexists(loc, name.c_str(), H5P_DEFAULT) <= 0) (g.*fail)(name, "missing dataset");
    Handle set(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.ok()) (g.*fail)(name, "cannot open the dataset");
    Handle space(H5Dget_space(set.get()), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    hsize_t dims[4] = {0, 0, 0, 0};
    bool fits = rank == static_cast<int>(trailing.size()) + 1 && rank <= 4 && H5Sget_simple_extent_dims(space.get(), dims, nullptr) >= 0;
    for (std::size_t k = 0; fits && k < trailing.size(); ++k) fits = dims[k + 1] == trailing[k];
    if (!fits) {
        std::string shape = "n";
        for (hsize_t d : trailing) shape += fmt::format(" x {}", d);
        (g.*fail)(name, "expected an array of shape " + shape);
    }
    if (expected_rows >= 0 && dims[0] != static_cast<hsize_t>(expected_rows))
        (g.*fail)(name, fmt::format("{} rows, expected {}", dims[0], expected_rows));
    std::size_t count = dims[0];
    for (hsize_t d : trailing) count *= d;
    out.resize(count);
    if (!out.empty() && H5Dread(set.get(), memory_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
        (g.*fail)(name, "cannot read the values (wrong type, or a damaged file)");
}

namespace {

// The trailing dimensions of an array read by rows of `slots` (0: one item a row) of an item
// of shape `item`; expected rows counted in items become rows of slots.
std::vector<hsize_t> trailing_of(std::size_t slots, std::vector<hsize_t> item) {
    std::vector<hsize_t> dims;
    if (slots > 0) dims.push_back(slots);
    dims.insert(dims.end(), item.begin(), item.end());
    return dims;
}
std::int64_t rows_of(std::int64_t expected_items, std::size_t slots) {
    return expected_items < 0 || slots == 0 ? expected_items : expected_items / static_cast<std::int64_t>(slots);
}

}  // namespace

std::vector<double> StateGroup::doubles(const std::string& name, std::int64_t expected, std::size_t slots) const {
    std::vector<double> v;
    read_numeric(*this, id_, name, trailing_of(slots, {}), rows_of(expected, slots), v, &StateGroup::fail_read);
    return v;
}
std::vector<std::int64_t> StateGroup::integers(const std::string& name, std::int64_t expected, std::size_t slots) const {
    std::vector<std::int64_t> v;
    read_numeric(*this, id_, name, trailing_of(slots, {}), rows_of(expected, slots), v, &StateGroup::fail_read);
    return v;
}
std::vector<std::uint32_t> StateGroup::indices(const std::string& name, std::int64_t expected, std::size_t slots) const {
    std::vector<std::uint32_t> v;
    read_numeric(*this, id_, name, trailing_of(slots, {}), rows_of(expected, slots), v, &StateGroup::fail_read);
    return v;
}
std::vector<std::uint8_t> StateGroup::flags(const std::string& name, std::int64_t expected, std::size_t slots) const {
    std::vector<std::uint8_t> v;
    read_numeric(*this, id_, name, trailing_of(slots, {}), rows_of(expected, slots), v, &StateGroup::fail_read);
    return v;
}
std::vector<Vec2> StateGroup::vectors(const std::string& name, std::int64_t expected, std::size_t slots) const {
    std::vector<double> flat;
    read_numeric(*this, id_, name, trailing_of(slots, {2}), rows_of(expected, slots), flat, &StateGroup::fail_read);
    std::vector<Vec2> v(flat.size() / 2);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = {flat[2 * i], flat[2 * i + 1]};
    return v;
}

std::vector<std::string> StateGroup::strings(const std::string& name, std::int64_t expected) const {
    if (H5Lexists(id_, name.c_str(), H5P_DEFAULT) <= 0) fail_read(name, "missing dataset");
    Handle set(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.ok()) fail_read(name, "cannot open the dataset");
    Handle space(H5Dget_space(set.get()), H5Sclose);
    hsize_t rows = 0;
    if (H5Sget_simple_extent_ndims(space.get()) != 1 || H5Sget_simple_extent_dims(space.get(), &rows, nullptr) < 0)
        fail_read(name, "expected a one-dimensional array of strings");
    if (expected >= 0 && rows != static_cast<hsize_t>(expected)) fail_read(name, fmt::format("{} rows, expected {}", rows, expected));
    std::vector<char*> raw(rows, nullptr);
    const Handle type = string_type();
    if (rows > 0 && H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()) < 0)
        fail_read(name, "cannot read the strings");
    std::vector<std::string> out;
    for (char* s : raw) out.emplace_back(s ? s : "");
    if (rows > 0) H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, raw.data());
    return out;
}

namespace {

// Opens attribute name of loc, or nothing.
hid_t open_attribute(hid_t loc, const std::string& name) {
    if (H5Aexists(loc, name.c_str()) <= 0) return -1;
    return H5Aopen(loc, name.c_str(), H5P_DEFAULT);
}

}  // namespace

double StateGroup::number(const std::string& name) const {
    Handle attribute(open_attribute(id_, name), H5Aclose);
    double value = 0.0;
    if (!attribute.ok()) fail_read(name, "missing attribute");
    if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) fail_read(name, "not a number");
    return value;
}

std::int64_t StateGroup::integer(const std::string& name) const {
    Handle attribute(open_attribute(id_, name), H5Aclose);
    std::int64_t value = 0;
    if (!attribute.ok()) fail_read(name, "missing attribute");
    Handle stored(H5Aget_type(attribute.get()), H5Tclose);
    if (H5Tget_class(stored.get()) != H5T_INTEGER) fail_read(name, "not an integer");
    if (H5Aread(attribute.get(), H5T_NATIVE_INT64, &value) < 0) fail_read(name, "not an integer");
    return value;
}

std::string StateGroup::text(const std::string& name) const {
    Handle attribute(open_attribute(id_, name), H5Aclose);
    if (!attribute.ok()) fail_read(name, "missing attribute");
    Handle stored(H5Aget_type(attribute.get()), H5Tclose);
    if (H5Tget_class(stored.get()) != H5T_STRING || H5Tis_variable_str(stored.get()) <= 0) fail_read(name, "not a string");
    char* raw = nullptr;
    const Handle type = string_type();
    if (H5Aread(attribute.get(), type.get(), &raw) < 0) fail_read(name, "not a string");
    std::string value = raw ? raw : "";
    H5free_memory(raw);
    return value;
}

// ---- the world's groups ----------------------------------------------------------------------

// What settling did before t = 0: summary.json reports it, also for a restarted run.
void write_settling(StateGroup& g, const SettlingRecord& r) {
    g.set("time_s", r.time_s);
    g.set("steps", r.steps);
    g.set("friction_held", std::int64_t{r.friction_held});
    g.set("kinetic_ratio", r.kinetic_ratio);
    g.set("largest_move_m", r.largest_move_m);
    g.set("largest_move_body", r.largest_move_body);
    g.set("largest_turn_rad", r.largest_turn_rad);
    g.set("largest_turn_body", r.largest_turn_body);
}

void check_live_limit_ratio(const std::string& file, const std::string& group, double ratio, double ratio_bound_s,
                            std::int64_t estimates) {
    const auto refuse = [&](const std::string& what) {
        throw InputError({file, "", 0, 0}, fmt::format("not a readable blockdem state file: {}/{}", group, what));
    };
    constexpr double max_ratio = 100.0;
    const bool none = ratio == 0.0;
    if (!(none || (ratio >= 1.0 && ratio <= max_ratio)))
        refuse(fmt::format("limit_ratio ({:g}) is neither 0 nor between 1 and {:g}", ratio, max_ratio));
    if (!std::isfinite(ratio_bound_s) || !(none ? ratio_bound_s >= 0.0 : ratio_bound_s > 0.0))
        refuse(fmt::format("ratio_bound_s ({:g}) is not a finite bound{}", ratio_bound_s, none ? "" : " above 0"));
    if (estimates < 0) refuse(fmt::format("estimates ({}) is negative", estimates));
}

SettlingRecord read_settling(const StateGroup& g) {
    SettlingRecord r;
    r.time_s = g.number("time_s");
    r.steps = g.integer("steps");
    r.friction_held = g.integer("friction_held") != 0;
    r.kinetic_ratio = g.number("kinetic_ratio");
    r.largest_move_m = g.number("largest_move_m");
    r.largest_move_body = g.text("largest_move_body");
    r.largest_turn_rad = g.number("largest_turn_rad");
    r.largest_turn_body = g.text("largest_turn_body");
    return r;
}

namespace {

template <class T, class Field>
std::vector<T> column(const std::vector<PairContact>& contacts, Field field) {
    std::vector<T> out;
    out.reserve(contacts.size());
    for (const PairContact& p : contacts) out.push_back(field(p));
    return out;
}

// Per contact point k (0, 1) of every pair: an n x 2 array, row = pair.
template <class T, class Field>
std::vector<T> point_column(const std::vector<PairContact>& contacts, Field field) {
    std::vector<T> out;
    out.reserve(2 * contacts.size());
    for (const PairContact& p : contacts)
        for (const ContactPoint& point : p.points) out.push_back(field(point));
    return out;
}

void write_contacts(StateGroup g, const std::vector<PairContact>& c) {
    g.write("a", column<std::uint32_t>(c, [](const PairContact& p) { return p.a; }));
    g.write("b", column<std::uint32_t>(c, [](const PairContact& p) { return p.b; }));
    g.write("part_a", column<std::uint32_t>(c, [](const PairContact& p) { return p.part_a; }));
    g.write("part_b", column<std::uint32_t>(c, [](const PairContact& p) { return p.part_b; }));
    g.write("count", column<std::uint32_t>(c, [](const PairContact& p) { return p.count; }));
    g.write("reference", column<std::uint32_t>(c, [](const PairContact& p) { return p.reference; }));
    g.write("normal", column<Vec2>(c, [](const PairContact& p) { return p.normal; }));
    g.write("stiffness_scale", column<double>(c, [](const PairContact& p) { return p.stiffness_scale; }));
    g.write("axis_separating", column<std::uint32_t>(c, [](const PairContact& p) { return p.axis_cache.separating; }));
    g.write("axis_incident", column<std::uint32_t>(c, [](const PairContact& p) { return p.axis_cache.incident; }));
    g.write("axis_others_max_separation_m",
            column<double>(c, [](const PairContact& p) { return p.axis_cache.others_max_separation_m; }));
    g.write("axis_drift_m", column<double>(c, [](const PairContact& p) { return p.axis_cache.drift_m; }));
    g.write("axis_incident_margin", column<double>(c, [](const PairContact& p) { return p.axis_cache.incident_margin; }));
    g.write("axis_turn_rad", column<double>(c, [](const PairContact& p) { return p.axis_cache.turn_rad; }));
    // The two point slots of each pair, slot 0 then slot 1 (a slot at or beyond count is unused).
    g.write("point_feature", point_column<std::uint32_t>(c, [](const ContactPoint& q) { return q.feature; }), 2);
    g.write("point_m", point_column<Vec2>(c, [](const ContactPoint& q) { return q.point_m; }), 2);
    g.write("point_overlap_m", point_column<double>(c, [](const ContactPoint& q) { return q.overlap_m; }), 2);
    g.write("point_normal_force_n", point_column<double>(c, [](const ContactPoint& q) { return q.normal_force_n; }), 2);
    g.write("point_shear_spring_n", point_column<double>(c, [](const ContactPoint& q) { return q.shear_spring_n; }), 2);
    g.write("point_shear_force_n", point_column<double>(c, [](const ContactPoint& q) { return q.shear_force_n; }), 2);
    g.write("point_normal_dashpot_n", point_column<double>(c, [](const ContactPoint& q) { return q.normal_dashpot_n; }), 2);
    g.write("point_shear_dashpot_n", point_column<double>(c, [](const ContactPoint& q) { return q.shear_dashpot_n; }), 2);
    g.write("point_sliding", point_column<std::uint8_t>(c, [](const ContactPoint& q) { return std::uint8_t(q.sliding); }), 2);
    g.write("point_bond", point_column<std::uint8_t>(c, [](const ContactPoint& q) { return std::uint8_t(q.bond); }), 2);
    g.write("point_dilation_m", point_column<double>(c, [](const ContactPoint& q) { return q.dilation_m; }), 2);
    std::vector<std::uint32_t> broken;
    for (const PairContact& p : c) broken.insert(broken.end(), p.broken_features, p.broken_features + 2);
    g.write("broken_features", broken, 2);
}

std::vector<PairContact> read_contacts(const StateGroup& g, std::size_t body_count) {
    const std::vector<std::uint32_t> a = g.indices("a");
    const auto n = static_cast<std::int64_t>(a.size());
    const std::vector<std::uint32_t> b = g.indices("b", n), count = g.indices("count", n), reference = g.indices("reference", n);
    const std::vector<Vec2> normal = g.vectors("normal", n);
    const std::vector<double> scale = g.doubles("stiffness_scale", n);
    const std::vector<std::uint32_t> separating = g.indices("axis_separating", n), incident = g.indices("axis_incident", n);
    const std::vector<double> others = g.doubles("axis_others_max_separation_m", n), drift = g.doubles("axis_drift_m", n),
                              margin = g.doubles("axis_incident_margin", n), turn = g.doubles("axis_turn_rad", n);
    const std::vector<std::uint32_t> feature = g.indices("point_feature", 2 * n, 2);
    const std::vector<Vec2> point = g.vectors("point_m", 2 * n, 2);
    const std::vector<double> overlap = g.doubles("point_overlap_m", 2 * n, 2), normal_force = g.doubles("point_normal_force_n", 2 * n, 2),
                              spring = g.doubles("point_shear_spring_n", 2 * n, 2), shear = g.doubles("point_shear_force_n", 2 * n, 2),
                              normal_dashpot = g.doubles("point_normal_dashpot_n", 2 * n, 2),
                              shear_dashpot = g.doubles("point_shear_dashpot_n", 2 * n, 2);
    const std::vector<std::uint8_t> sliding = g.flags("point_sliding", 2 * n, 2);
    // (Files written before bodies had parts: every body was convex, one part with the body's id.)
    const std::vector<std::uint32_t> part_a = g.has("part_a") ? g.indices("part_a", n) : a;
    const std::vector<std::uint32_t> part_b = g.has("part_b") ? g.indices("part_b", n) : b;
    // (Files written before bonds existed have no bond column: no point was bonded then.)
    const std::vector<std::uint8_t> bond =
        g.has("point_bond") ? g.flags("point_bond", 2 * n, 2) : std::vector<std::uint8_t>(2 * a.size(), 0);
    // (Files written before joints dilated have no dilation column: no point had dilated.)
    const std::vector<double> dilation =
        g.has("point_dilation_m") ? g.doubles("point_dilation_m", 2 * n, 2) : std::vector<double>(2 * a.size(), 0.0);
    // (Files written before broken corners were remembered have none.)
    const std::vector<std::uint32_t> broken =
        g.has("broken_features") ? g.indices("broken_features", 2 * n, 2) : std::vector<std::uint32_t>(2 * a.size(), no_feature);
    std::vector<PairContact> out(a.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        PairContact& p = out[i];
        p.broken_features[0] = broken[2 * i];
        p.broken_features[1] = broken[2 * i + 1];
        // The table is sorted by (part_a, part_b), with a < b: the merge and the force sums rely on it.
        const bool sorted = i == 0 || out[i - 1].part_a < part_a[i] ||
                            (out[i - 1].part_a == part_a[i] && out[i - 1].part_b < part_b[i]);
        const bool bonds_valid = bond[2 * i] <= std::uint8_t(BondState::broken_shear) &&
                                 bond[2 * i + 1] <= std::uint8_t(BondState::broken_shear);
        if (a[i] >= b[i] || b[i] >= body_count || count[i] > 2 || !sorted || !bonds_valid)
            throw InputError({g.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: {}: pair {} is not a "
                                                               "valid entry of the contact table", g.path(), i + 1));
        p.a = a[i];
        p.b = b[i];
        p.part_a = part_a[i];
        p.part_b = part_b[i];
        p.count = count[i];
        p.reference = reference[i];
        p.normal = normal[i];
        p.stiffness_scale = scale[i];
        p.axis_cache = {separating[i], incident[i], others[i], drift[i], margin[i], turn[i]};
        for (std::size_t k = 0; k < 2; ++k) {
            const std::size_t j = 2 * i + k;
            p.points[k] = {feature[j], sliding[j] != 0, static_cast<BondState>(bond[j]), point[j], overlap[j], normal_force[j],
                           spring[j], shear[j], normal_dashpot[j], shear_dashpot[j], dilation[j]};
        }
    }
    return out;
}

// The interior points of sub-contacts (contact/sub_contacts.hpp): each pair's count, then its
// points in one flat list, pair after pair.
void write_sub_contacts(StateGroup g, const std::vector<SubContacts>& sub) {
    std::vector<std::uint32_t> count, memory;
    std::vector<Vec2> normal, memory_first;
    std::vector<ContactPoint> points;
    for (const SubContacts& s : sub) {
        count.push_back(s.count);
        normal.push_back(s.normal);
        points.insert(points.end(), s.points, s.points + s.count);
        memory.push_back(s.broken_memory);
        memory_first.push_back(s.memory_first_m);
    }
    auto points_of = [&]<class T>(auto field) {
        std::vector<T> out;
        for (const ContactPoint& q : points) out.push_back(field(q));
        return out;
    };
    g.write("count", count);
    g.write("normal", normal);
    g.write("broken_memory", memory);
    g.write("memory_first_m", memory_first);
    g.write("point_feature", points_of.operator()<std::uint32_t>([](const ContactPoint& q) { return q.feature; }));
    g.write("point_m", points_of.operator()<Vec2>([](const ContactPoint& q) { return q.point_m; }));
    g.write("point_overlap_m", points_of.operator()<double>([](const ContactPoint& q) { return q.overlap_m; }));
    g.write("point_normal_force_n", points_of.operator()<double>([](const ContactPoint& q) { return q.normal_force_n; }));
    g.write("point_shear_spring_n", points_of.operator()<double>([](const ContactPoint& q) { return q.shear_spring_n; }));
    g.write("point_shear_force_n", points_of.operator()<double>([](const ContactPoint& q) { return q.shear_force_n; }));
    g.write("point_normal_dashpot_n", points_of.operator()<double>([](const ContactPoint& q) { return q.normal_dashpot_n; }));
    g.write("point_shear_dashpot_n", points_of.operator()<double>([](const ContactPoint& q) { return q.shear_dashpot_n; }));
    g.write("point_sliding", points_of.operator()<std::uint8_t>([](const ContactPoint& q) { return std::uint8_t(q.sliding); }));
    g.write("point_bond", points_of.operator()<std::uint8_t>([](const ContactPoint& q) { return std::uint8_t(q.bond); }));
    g.write("point_dilation_m", points_of.operator()<double>([](const ContactPoint& q) { return q.dilation_m; }));
}

std::vector<SubContacts> read_sub_contacts(const StateGroup& g, std::size_t pair_count) {
    const std::vector<std::uint32_t> count = g.indices("count", static_cast<std::int64_t>(pair_count));
    const std::vector<Vec2> normal = g.vectors("normal", static_cast<std::int64_t>(pair_count));
    std::int64_t total = 0;
    for (std::size_t i = 0; i < count.size(); ++i) {
        if (count[i] > max_sub_contacts - 2)
            throw InputError({g.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: {}: pair {} has {} "
                                                               "interior points, at most {}", g.path(), i + 1, count[i],
                                                               max_sub_contacts - 2));
        total += count[i];
    }
    const std::vector<std::uint32_t> feature = g.indices("point_feature", total);
    const std::vector<Vec2> point = g.vectors("point_m", total);
    const std::vector<double> overlap = g.doubles("point_overlap_m", total), normal_force = g.doubles("point_normal_force_n", total),
                              spring = g.doubles("point_shear_spring_n", total), shear = g.doubles("point_shear_force_n", total),
                              normal_dashpot = g.doubles("point_normal_dashpot_n", total),
                              shear_dashpot = g.doubles("point_shear_dashpot_n", total);
    const std::vector<std::uint8_t> sliding = g.flags("point_sliding", total), bond = g.flags("point_bond", total);
    const std::vector<double> dilation =
        g.has("point_dilation_m") ? g.doubles("point_dilation_m", total) : std::vector<double>(total, 0.0);
    // (Files from before the broken points' memory have none.)
    const std::vector<std::uint32_t> memory = g.has("broken_memory") ? g.indices("broken_memory", static_cast<std::int64_t>(pair_count))
                                                                     : std::vector<std::uint32_t>(pair_count, 0);
    const std::vector<Vec2> memory_first = g.has("memory_first_m") ? g.vectors("memory_first_m", static_cast<std::int64_t>(pair_count))
                                                                   : std::vector<Vec2>(pair_count);
    std::vector<SubContacts> out(pair_count);
    std::size_t j = 0;
    for (std::size_t i = 0; i < pair_count; ++i) {
        out[i].count = count[i];
        out[i].normal = normal[i];
        // (2 bits a point, 1 or 2 for a broken one: sub_contacts.hpp.)
        if ((memory[i] & (memory[i] >> 1) & 0x55555555u) != 0)
            throw InputError({g.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: {}: pair {} remembers "
                                                               "an invalid bond state", g.path(), i + 1));
        out[i].broken_memory = memory[i];
        out[i].memory_first_m = memory_first[i];
        for (std::uint32_t k = 0; k < count[i]; ++k, ++j) {
            if (bond[j] > std::uint8_t(BondState::broken_shear))
                throw InputError({g.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: {}: point {} has no "
                                                                   "valid bond state", g.path(), j + 1));
            out[i].points[k] = {feature[j], sliding[j] != 0, static_cast<BondState>(bond[j]), point[j], overlap[j], normal_force[j],
                                spring[j], shear[j], normal_dashpot[j], shear_dashpot[j], dilation[j]};
        }
    }
    return out;
}

void write_energy(StateGroup g, const EnergyLedger& e) {
    g.set("kinetic_j", e.kinetic_j);
    g.set("gravitational_j", e.gravitational_j);
    g.set("elastic_j", e.elastic_j);
    g.set("normal_dashpot_j", e.normal_dashpot_j);
    g.set("shear_dashpot_j", e.shear_dashpot_j);
    g.set("friction_j", e.friction_j);
    g.set("table_work_j", e.table_work_j);
    g.set("initial_j", e.initial_j);
    g.set("initial_gravitational_j", e.initial_gravitational_j);
    g.set("peak_scale_j", e.peak_scale_j);
    g.set("removed_j", e.removed_j);
    g.set("tilt_work_j", e.tilt_work_j);
    g.set("bond_breakage_j", e.bond_breakage_j);
    g.set("external_work_j", e.external_work_j);
}

EnergyLedger read_energy(const StateGroup& g) {
    EnergyLedger e;
    e.kinetic_j = g.number("kinetic_j");
    e.gravitational_j = g.number("gravitational_j");
    e.elastic_j = g.number("elastic_j");
    e.normal_dashpot_j = g.number("normal_dashpot_j");
    e.shear_dashpot_j = g.number("shear_dashpot_j");
    e.friction_j = g.number("friction_j");
    e.table_work_j = g.number("table_work_j");
    e.initial_j = g.number("initial_j");
    e.initial_gravitational_j = g.number("initial_gravitational_j");
    e.peak_scale_j = g.number("peak_scale_j");
    e.removed_j = g.number("removed_j");
    e.tilt_work_j = g.number("tilt_work_j");
    e.bond_breakage_j = g.has("bond_breakage_j") ? g.number("bond_breakage_j") : 0.0;
    // (Files written before the ledger kept it: no caller's load had done work, or it was lost.)
    e.external_work_j = g.has("external_work_j") ? g.number("external_work_j") : 0.0;
    return e;
}

void write_stability(StateGroup g, const StabilityWatch& s) {
    g.set("start_bound_s", s.start_bound_s);
    g.set("limit_ratio", s.limit_ratio);
    g.set("ratio_bound_s", s.ratio_bound_s);
    g.set("estimates", s.estimates);
    g.set("least_limit_s", s.least_limit_s);
    g.set("least_limit_body", s.least_limit_body);
    g.set("least_limit_time_s", s.least_limit_time_s);
    g.set("first_exceeded_s", s.first_exceeded_s);
    g.set("exceeded_body", s.exceeded_body);
    g.set("max_overlap_ratio", s.max_overlap_ratio);
    g.set("max_overlap_time_s", s.max_overlap_time_s);
    g.set("max_overlap_pair_a", std::int64_t{s.max_overlap_pair_a});
    g.set("max_overlap_pair_b", std::int64_t{s.max_overlap_pair_b});
    g.set("max_overlap_m", s.max_overlap_m);
    g.set("max_overlap_kn_N_m", s.max_overlap_kn_N_m);
}

// has_ratio: the file holds the live limit's ratio (a file saved before the watch kept it does
// not; read_world then takes the file's own start ratio).
StabilityWatch read_stability(const StateGroup& g, bool& has_ratio) {
    StabilityWatch s;
    s.start_bound_s = g.number("start_bound_s");
    has_ratio = g.has("limit_ratio");
    if (has_ratio) {
        s.limit_ratio = g.number("limit_ratio");
        s.ratio_bound_s = g.number("ratio_bound_s");
        s.estimates = g.integer("estimates");
    }
    s.least_limit_s = g.number("least_limit_s");
    s.least_limit_body = g.text("least_limit_body");
    s.least_limit_time_s = g.number("least_limit_time_s");
    s.first_exceeded_s = g.number("first_exceeded_s");
    s.exceeded_body = g.text("exceeded_body");
    s.max_overlap_ratio = g.number("max_overlap_ratio");
    s.max_overlap_time_s = g.number("max_overlap_time_s");
    s.max_overlap_pair_a = static_cast<std::uint32_t>(g.integer("max_overlap_pair_a"));
    s.max_overlap_pair_b = static_cast<std::uint32_t>(g.integer("max_overlap_pair_b"));
    s.max_overlap_m = g.number("max_overlap_m");
    s.max_overlap_kn_N_m = g.number("max_overlap_kn_N_m");
    return s;
}

// The live limit's ratio as read, or from a file without it (saved before the 2-D watch kept it),
// the file's own start ratio.
void read_live_limit_ratio(const std::string& file, StabilityWatch& s, bool has_ratio, double critical_dt_s) {
    if (!has_ratio) {
        if (!(s.start_bound_s > 0.0))  // (infinite: nothing touched at the start)
            throw InputError({file, "", 0, 0}, fmt::format("not a readable blockdem state file: /stability/start_bound_s "
                                                           "({:g}) is not positive", s.start_bound_s));
        s.limit_ratio = start_limit_ratio(critical_dt_s, s.start_bound_s);
        s.ratio_bound_s = s.limit_ratio > 0.0 ? s.start_bound_s : 0.0;
        s.estimates = 0;
    }
    check_live_limit_ratio(file, "/stability", s.limit_ratio, s.ratio_bound_s, s.estimates);
}

void write_world(StateGroup& root, const WorldState& s) {
    StateGroup clock = root.create_group("clock");
    clock.set("time_s", s.time_s);
    clock.set("step_index", s.step_index);
    clock.set("dt_s", s.dt_s);
    clock.set("critical_dt_s", s.critical_dt_s);
    clock.set("proven_stable_dt_s", s.proven_stable_dt_s);
    clock.set("settling_time_s", s.settling_time_s);
    clock.set("velocities_staggered", std::int64_t{s.velocities_staggered});
    clock.set("broad_phase_rebuilds", s.broad_phase_rebuilds);

    StateGroup b = root.create_group("bodies");
    b.write("name", s.name);
    std::vector<std::string> kinds;
    for (BodyKind k : s.kind) kinds.emplace_back(to_string(k));
    b.write("kind", kinds);
    b.write("vertex_count", s.vertex_count);
    b.write("local_vertices_m", s.local_vertices_m);
    b.write("mass_kg", s.mass_kg);
    b.write("inertia_kg_m2", s.inertia_kg_m2);
    b.write("is_static", s.is_static);
    b.write("position_m", s.position_m);
    b.write("rotation_rad", s.rotation_rad);
    b.write("velocity_m_s", s.velocity_m_s);
    b.write("angular_velocity_rad_s", s.angular_velocity_rad_s);
    b.write("velocity_at_t_m_s", s.velocity_at_t_m_s);
    b.write("angular_velocity_at_t_rad_s", s.angular_velocity_at_t_rad_s);
    b.write("initial_position_m", s.initial_position_m);
    b.write("world_vertices_m", s.world_vertices_m);
    b.write("world_normals", s.world_normals);
    b.write("position_at_rebuild_m", s.position_at_rebuild_m);
    b.write("rotation_at_rebuild_rad", s.rotation_at_rebuild_rad);

    write_contacts(root.create_group("contacts"), s.contacts);
    // (Only with sub-contacts: the files of two-point runs stay as they were.)
    if (!s.sub_contacts.empty()) write_sub_contacts(root.create_group("sub_contacts"), s.sub_contacts);
    write_energy(root.create_group("energy"), s.energy);
    write_stability(root.create_group("stability"), s.stability);
    if (s.settling) {
        StateGroup settling = root.create_group("settling");
        write_settling(settling, *s.settling);
    }

    StateGroup d = root.create_group("domain");
    std::vector<std::uint32_t> body;
    std::vector<double> time_s;
    std::vector<Vec2> position_m, velocity_m_s;
    for (const BodyLeftModel& l : s.left) {
        body.push_back(l.body);
        time_s.push_back(l.time_s);
        position_m.push_back(l.position_m);
        velocity_m_s.push_back(l.velocity_m_s);
    }
    d.write("left_body", body);
    d.write("left_time_s", time_s);
    d.write("left_position_m", position_m);
    d.write("left_velocity_m_s", velocity_m_s);
    // (Only while a caller's loads exist: the files of runs without them stay as they were.)
    if (s.external_loads.any()) write_external_loads(root.create_group("external_loads"), s.external_loads);
}

WorldState read_world(const StateGroup& root) {
    WorldState s;
    const StateGroup clock = root.open_group("clock");
    s.time_s = clock.number("time_s");
    s.step_index = clock.integer("step_index");
    s.dt_s = clock.number("dt_s");
    s.critical_dt_s = clock.number("critical_dt_s");
    s.proven_stable_dt_s = clock.number("proven_stable_dt_s");
    s.settling_time_s = clock.number("settling_time_s");
    s.velocities_staggered = clock.integer("velocities_staggered") != 0;
    s.broad_phase_rebuilds = clock.integer("broad_phase_rebuilds");

    const StateGroup b = root.open_group("bodies");
    s.name = b.strings("name");
    const auto n = static_cast<std::int64_t>(s.name.size());
    for (const std::string& kind : b.strings("kind", n)) {
        if (kind == "dynamic") s.kind.push_back(BodyKind::dynamic);
        else if (kind == "fixed") s.kind.push_back(BodyKind::fixed);
        else if (kind == "driven") s.kind.push_back(BodyKind::driven);
        else throw InputError({b.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: /bodies/kind: "
                                                                "unknown kind '{}'", kind));
    }
    s.vertex_count = b.indices("vertex_count", n);
    std::int64_t corners = 0;
    for (std::uint32_t c : s.vertex_count) corners += c;
    s.local_vertices_m = b.vectors("local_vertices_m", corners);
    if (b.has("mass_kg")) s.mass_kg = b.doubles("mass_kg", n);  // (files before them lack them)
    if (b.has("inertia_kg_m2")) s.inertia_kg_m2 = b.doubles("inertia_kg_m2", n);
    s.is_static = b.flags("is_static", n);
    s.position_m = b.vectors("position_m", n);
    s.rotation_rad = b.doubles("rotation_rad", n);
    s.velocity_m_s = b.vectors("velocity_m_s", n);
    s.angular_velocity_rad_s = b.doubles("angular_velocity_rad_s", n);
    s.velocity_at_t_m_s = b.vectors("velocity_at_t_m_s", n);
    s.angular_velocity_at_t_rad_s = b.doubles("angular_velocity_at_t_rad_s", n);
    s.initial_position_m = b.vectors("initial_position_m", n);
    s.world_vertices_m = b.vectors("world_vertices_m", corners);
    s.world_normals = b.vectors("world_normals", corners);
    s.position_at_rebuild_m = b.vectors("position_at_rebuild_m");
    s.rotation_at_rebuild_rad = b.doubles("rotation_at_rebuild_rad", static_cast<std::int64_t>(s.position_at_rebuild_m.size()));
    if (!s.position_at_rebuild_m.empty() && static_cast<std::int64_t>(s.position_at_rebuild_m.size()) != n)
        throw InputError({b.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: /bodies/position_at_rebuild_m: "
                                                           "{} rows, expected {}", s.position_at_rebuild_m.size(), n));

    s.contacts = read_contacts(root.open_group("contacts"), s.name.size());
    if (root.has("sub_contacts")) s.sub_contacts = read_sub_contacts(root.open_group("sub_contacts"), s.contacts.size());
    s.energy = read_energy(root.open_group("energy"));
    bool has_ratio = false;
    s.stability = read_stability(root.open_group("stability"), has_ratio);
    read_live_limit_ratio(root.file(), s.stability, has_ratio, s.critical_dt_s);
    if (root.has("settling")) s.settling = read_settling(root.open_group("settling"));

    const StateGroup d = root.open_group("domain");
    const std::vector<std::uint32_t> body = d.indices("left_body");
    const auto left = static_cast<std::int64_t>(body.size());
    const std::vector<double> time_s = d.doubles("left_time_s", left);
    const std::vector<Vec2> position_m = d.vectors("left_position_m", left), velocity_m_s = d.vectors("left_velocity_m_s", left);
    for (std::size_t i = 0; i < body.size(); ++i) {
        if (body[i] >= s.name.size())
            throw InputError({d.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: /domain/left_body: "
                                                               "body {} of {}", body[i], s.name.size()));
        s.left.push_back({body[i], time_s[i], position_m[i], velocity_m_s[i]});
    }
    // (A file without the group, from a run without loads or from before they were kept: none.)
    if (root.has("external_loads")) s.external_loads = read_external_loads(root.open_group("external_loads"), s.name.size());
    return s;
}

}  // namespace

namespace {

// The file is built in memory (HDF5's core driver) and written through OutputFile, so that a
// full disk is met by the project's own checks: the library never holds a half-written file.
// write_groups fills the root after the run's facts.
void write_state_image(const std::filesystem::path& file, const StateFileInfo& info, double time_s,
                       std::int64_t step_index, const std::function<void(StateGroup&)>& write_groups) {
    quiet_hdf5();
    std::string image;
    {
        Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
        if (!access.ok() || H5Pset_fapl_core(access.get(), 1 << 20, 0) < 0)
            throw OutputError(fmt::format("{}: cannot set up the state file in memory", file.string()));
        const hid_t id = H5Fcreate(file.filename().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
        if (id < 0) throw OutputError(fmt::format("{}: cannot create the state file in memory", file.string()));
        StateGroup root(id, file.string(), "/");
        root.set("format", std::string(format_name));
        root.set("format_version", format_version);
        root.set("reason", info.reason);
        root.set("scenario", info.scenario);
        root.set("scenario_toml", info.scenario_toml);
        root.set("run_folder", info.run_folder);
        root.set("output_rows", info.output_rows);
        root.set("time_s", time_s);
        root.set("step_index", step_index);
        write_groups(root);
        const ssize_t size = H5Fflush(id, H5F_SCOPE_GLOBAL) < 0 ? -1 : H5Fget_file_image(id, nullptr, 0);
        if (size <= 0) throw OutputError(fmt::format("{}: cannot complete the state file in memory", file.string()));
        image.resize(static_cast<std::size_t>(size));
        if (H5Fget_file_image(id, image.data(), image.size()) != size)
            throw OutputError(fmt::format("{}: cannot complete the state file in memory", file.string()));
    }
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    if (ec) throw OutputError(fmt::format("{}: cannot create the folder: {}", file.parent_path().string(), ec.message()));
    // Whole or not at all, and an earlier file of the same name stays until the new one is whole.
    std::filesystem::path partial = file;
    partial += ".partial";
    try {
        write_output_file(partial, image);
    } catch (const OutputError& e) {
        throw OutputError(fmt::format("{} (state file {})", e.what(), file.string()));
    }
    std::filesystem::rename(partial, file, ec);
    if (ec) {
        std::filesystem::remove(partial, ec);
        throw OutputError(fmt::format("{}: cannot write the state file: {}", file.string(), ec.message()));
    }
}

void write_parts(StateGroup& root, const std::vector<const StatePart*>& parts) {
    for (const StatePart* part : parts) {
        StateGroup g = root.create_group(part->state_group());
        part->save_state(g);
    }
}

}  // namespace

void write_state_file(const std::filesystem::path& file, const World& w, const StateFileInfo& info,
                      const std::vector<const StatePart*>& parts) {
    write_state_image(file, info, w.time_s, w.step_index, [&](StateGroup& root) {
        write_world(root, capture_state(w));
        write_parts(root, parts);
    });
}

void write_state_file(const std::filesystem::path& file, int dimension, double time_s, std::int64_t step_index,
                      const StateFileInfo& info, const std::function<void(StateGroup&)>& write_world,
                      const std::vector<const StatePart*>& parts) {
    write_state_image(file, info, time_s, step_index, [&](StateGroup& root) {
        root.set("dimension", static_cast<std::int64_t>(dimension));
        write_world(root);
        write_parts(root, parts);
    });
}

StateFile::StateFile(const std::filesystem::path& file) : file_(file) {
    quiet_hdf5();
    const InputLocation where{file.string(), "", 0, 0};
    if (std::filesystem::is_directory(file))
        throw InputError(where, "a folder, not a state file (a run's state files are in its state/ folder: t_*.h5)");
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) throw InputError(where, "no such state file");
    // (/dev/null, a pipe: it exists, so "no such file" would mislead.)
    if (!std::filesystem::is_regular_file(status))
        throw InputError(where, "not a regular file (a device, pipe or socket), so not a state file (an HDF5 file t_*.h5)");
    if (H5Fis_hdf5(file.c_str()) <= 0) throw InputError(where, "not an HDF5 file (not a blockdem state file)");
    const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) throw InputError(where, "cannot open the HDF5 file (damaged or truncated?)");
    root_ = std::make_shared<StateGroup>(id, file.string(), "/");
    if (!root_->has("format") || root_->text("format") != format_name)
        throw InputError(where, "an HDF5 file, but not a blockdem state file (no attribute format = \"blockdem state\")");
    const std::int64_t version = root_->integer("format_version");
    if (version != format_version)
        throw InputError(where, fmt::format("state file format version {}; this blockdem reads version {}", version,
                                            format_version));
    info_.reason = root_->text("reason");
    info_.scenario = root_->text("scenario");
    info_.scenario_toml = root_->text("scenario_toml");
    info_.run_folder = root_->text("run_folder");
    info_.output_rows = root_->integer("output_rows");
    // (A 2-D file has no dimension attribute: its world is in the fixed groups read here; a 3-D
    // file keeps its world in a part's group, io/state_file_3d.hpp.)
    dimension_ = root_->has("dimension") ? static_cast<int>(root_->integer("dimension")) : 2;
    if (dimension_ == 2) world_ = read_world(*root_);
}

void StateFile::restore(StatePart& part) const { part.restore_state(root_->open_group(part.state_group())); }
void write_ledger(StateGroup group, const EnergyLedger& ledger) { write_energy(std::move(group), ledger); }
EnergyLedger read_ledger(const StateGroup& group) { return read_energy(group); }

double StateFile::time_s() const { return root_->number("time_s"); }
std::int64_t StateFile::step_index() const { return root_->integer("step_index"); }

std::filesystem::path state_file_name(const std::filesystem::path& run_dir, std::int64_t step_index, double dt_s) {
    // Two times dt apart print differently once the last decimal is finer than dt.
    int decimals = 6;
    while (decimals < 17 && std::pow(10.0, -decimals) >= dt_s) ++decimals;
    return run_dir / "state" / fmt::format("t_{:.{}f}s.h5", static_cast<double>(step_index) * dt_s, decimals);
}

}  // namespace blockdem
