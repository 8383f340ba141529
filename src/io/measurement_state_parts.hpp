#pragma once
// The state of the measurements (io/sensor_keys.hpp) as groups of a run's state files
// (io/state_file.hpp), written only when the run has them, so that a restarted run writes
// sensors.csv, interfaces.csv and summary.json's "interfaces" as a run that never stopped:
//   /sensors     each filtered channel's running Butterworth state, and each relative sensor's
//                reading at the start (an LVDT reads from it);
//   /interfaces  every interface followed so far (world/interface_monitor.hpp: its pair, slip,
//                peaks, first touch), and how many rows interfaces.csv holds before the state
//                (a time has one row per pair then touching, so the rows are not the times).
#include <cstdint>
#include <string>

#include "io/interfaces_writer.hpp"
#include "io/sensors_writer.hpp"
#include "io/state_file.hpp"

namespace blockdem {

class SensorsStatePart : public StatePart {
public:
    explicit SensorsStatePart(SensorsWriter& writer) : writer_(writer) {}
    std::string state_group() const override { return "sensors"; }
    void save_state(StateGroup& group) const override;
    /// InputError when the state's sensors are not the scenario's (names, or filters).
    void restore_state(const StateGroup& group) override;

private:
    SensorsWriter& writer_;
};

class InterfacesStatePart : public StatePart {
public:
    InterfacesStatePart(InterfacesWriter& writer, const World& w) : writer_(writer), world_(w) {}
    std::string state_group() const override { return "interfaces"; }
    void save_state(StateGroup& group) const override;
    /// InputError when the state's interfaces are not the named pairs of the scenario.
    void restore_state(const StateGroup& group) override;

private:
    InterfacesWriter& writer_;
    const World& world_;   ///< its bodies bound the saved pairs
};

/// The rows of interfaces.csv written before the state (its /interfaces group, which the caller
/// checks is there), to cut the file back before the writer opens it.
std::int64_t interfaces_csv_rows(const StateFile& state);

}  // namespace blockdem
