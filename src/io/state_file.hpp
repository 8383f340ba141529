#pragma once
// State files: the complete state of a run between two steps, in HDF5 (docs/outputs.md, "State
// files"), written by `blockdem run --save-state`, `--save-state-every` and on an interruption,
// read by `--restart` and by a scenario's [simulation] initial_state.
//
// The world's part (world/world_state.hpp) has fixed groups (/clock, /bodies, /contacts,
// /energy, /stability, /domain, and /external_loads while a caller has loads:
// io/external_loads_state.hpp). Whatever else keeps state across the run (the response monitor
// behind summary.json, the VTK writer's frame list, a sensor's filter) is a StatePart: it writes
// and reads its own group, named by itself, so a new recorder adds its state without touching
// this file. Every dataset and attribute has its unit in its name, as in the code.
//
// A state file is written to NAME.partial and renamed when complete, so a failed write (a full
// disk) never leaves a torn state file and never replaces an earlier one.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "world/world_state.hpp"

namespace blockdem {

/// One group of a state file. Arrays are datasets (a Vec2 array is n x 2), scalars attributes.
/// Writing throws OutputError, reading InputError, each naming the file and the item.
class StateGroup {
public:
    StateGroup(std::int64_t id, std::string file, std::string path);
    ~StateGroup();
    StateGroup(StateGroup&& other) noexcept;
    StateGroup(const StateGroup&) = delete;
    StateGroup& operator=(const StateGroup&) = delete;
    StateGroup& operator=(StateGroup&&) = delete;

    /// A subgroup: created when writing, opened when reading.
    StateGroup create_group(const std::string& name);
    StateGroup open_group(const std::string& name) const;
    bool has(const std::string& name) const;

    /// slots > 0: the values come in rows of `slots` (n x slots, as the two point slots of
    /// each contact pair); a Vec2 adds a last dimension of 2.
    void write(const std::string& name, const std::vector<double>& values, std::size_t slots = 0);
    void write(const std::string& name, const std::vector<std::int64_t>& values, std::size_t slots = 0);
    void write(const std::string& name, const std::vector<std::uint32_t>& values, std::size_t slots = 0);
    void write(const std::string& name, const std::vector<std::uint8_t>& values, std::size_t slots = 0);
    void write(const std::string& name, const std::vector<Vec2>& values, std::size_t slots = 0);
    void write(const std::string& name, const std::vector<std::string>& values);
    void set(const std::string& name, double value);
    void set(const std::string& name, std::int64_t value);
    void set(const std::string& name, const std::string& value);

    /// Arrays, flat in item order; expected_size (items), when given, is checked; slots as in write.
    std::vector<double> doubles(const std::string& name, std::int64_t expected_size = -1, std::size_t slots = 0) const;
    std::vector<std::int64_t> integers(const std::string& name, std::int64_t expected_size = -1, std::size_t slots = 0) const;
    std::vector<std::uint32_t> indices(const std::string& name, std::int64_t expected_size = -1, std::size_t slots = 0) const;
    std::vector<std::uint8_t> flags(const std::string& name, std::int64_t expected_size = -1, std::size_t slots = 0) const;
    std::vector<Vec2> vectors(const std::string& name, std::int64_t expected_size = -1, std::size_t slots = 0) const;
    std::vector<std::string> strings(const std::string& name, std::int64_t expected_size = -1) const;
    double number(const std::string& name) const;
    std::int64_t integer(const std::string& name) const;
    std::string text(const std::string& name) const;

    const std::string& file() const { return file_; }
    const std::string& path() const { return path_; }

private:
    [[noreturn]] void fail_read(const std::string& name, const std::string& problem) const;
    [[noreturn]] void fail_write(const std::string& name) const;
    std::int64_t id_ = -1;   ///< hid_t
    std::string file_;       ///< for messages
    std::string path_;       ///< of this group in the file, "/" for the root
};

/// Something besides the world that keeps state across a run (see above).
class StatePart {
public:
    virtual ~StatePart() = default;
    virtual std::string state_group() const = 0;
    virtual void save_state(StateGroup& group) const = 0;
    virtual void restore_state(const StateGroup& group) = 0;
};

/// Facts about the run, kept at the file's root.
struct StateFileInfo {
    std::string reason;            ///< "save_state", "save_state_every", "interrupted"
    std::string scenario;          ///< the scenario file the run was started from
    std::string scenario_toml;     ///< the scenario as run (after --set), to recognise a changed one
    std::string run_folder;        ///< the run's folder, absolute
    std::int64_t output_rows = 0;  ///< rows of history.csv and energy.csv written before this state
};

/// Writes w's state and every part's group to file (see above). Throws OutputError.
void write_state_file(const std::filesystem::path& file, const World& w, const StateFileInfo& info,
                      const std::vector<const StatePart*>& parts);

/// Writes the state of a world of another dimension (3-D: io/state_file_3d.hpp): the run's facts,
/// the attribute dimension, the world's groups by write_world, and every part's group. Throws
/// OutputError.
void write_state_file(const std::filesystem::path& file, int dimension, double time_s, std::int64_t step_index,
                      const StateFileInfo& info, const std::function<void(StateGroup&)>& write_world,
                      const std::vector<const StatePart*>& parts);

/// The energy ledger's group (the same in both dimensions): /energy in a 2-D file.
void write_ledger(StateGroup group, const EnergyLedger& ledger);
/// What settling did before t = 0 (both dimensions): summary.json reports it, also for a restarted run.
void write_settling(StateGroup& group, const SettlingRecord& record);
SettlingRecord read_settling(const StateGroup& group);
EnergyLedger read_ledger(const StateGroup& group);
/// The live limit's ratio, its bound and the estimate count of a stability watch's group (group:
/// "/stability" or "/stability3d"), refused out of range with an InputError naming file and the
/// attribute: the ratio is 0 ("none yet", with a bound of 0 or more) or between 1 (below, the live
/// limit would fall under the proven bound) and 100 (the highest measured is 4; far above, the
/// watch would never report), with a finite bound above 0; estimates are not negative.
void check_live_limit_ratio(const std::string& file, const std::string& group, double ratio, double ratio_bound_s,
                            std::int64_t estimates);

/// An open state file. Throws InputError naming the file and the item for a missing, corrupt or
/// foreign file.
class StateFile {
public:
    explicit StateFile(const std::filesystem::path& file);
    /// The 2-D world (empty for a 3-D file: its world is a part's group).
    const WorldState& world() const { return world_; }
    /// 2 or 3 (a file without the attribute is 2-D).
    int dimension() const { return dimension_; }
    double time_s() const;             ///< [s] of the state
    std::int64_t step_index() const;   ///< the step the run goes on from
    const StateFileInfo& info() const { return info_; }
    /// Restores part from its group; InputError when the file has none.
    void restore(StatePart& part) const;
    bool has_group(const std::string& name) const { return root_->has(name); }
    /// The file's root, for a world of another dimension to read its groups.
    const StateGroup& root() const { return *root_; }
    const std::filesystem::path& path() const { return file_; }

private:
    std::filesystem::path file_;
    std::shared_ptr<StateGroup> root_;
    WorldState world_;
    StateFileInfo info_;
    int dimension_ = 2;
};

/// The name of the state file of step step_index in a run folder: the time it holds,
/// state/t_0.500000s.h5, with 6 decimals, or more when dt is 1e-6 s or less, so that no two
/// steps share a name.
std::filesystem::path state_file_name(const std::filesystem::path& run_dir, std::int64_t step_index, double dt_s);

}  // namespace blockdem
