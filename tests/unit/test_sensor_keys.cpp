// [[sensors]] and [output] interfaces (io/sensor_keys.hpp): what they read, and clear errors
// naming the file, the key and the sensor.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_error.hpp"
#include "io/scenario.hpp"
#include "support/scenario_text.hpp"

namespace blockdem {
namespace {

using testing::expect_contains;
std::filesystem::path write(const std::string& name, const std::string& text) { return testing::write_scenario("sensor-keys", name, text); }

const std::string base = R"(
[simulation]
duration = 1.0
dt = 1.0e-4

[contact]
kn = 2.0e4
ks = 2.0e4
mu = 0.3
e = 0.4

[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 4.0
height = 0.2
center = [0.0, -0.1]

[[bodies]]
name = "block"
shape = "rectangle"
width = 0.5
height = 0.2
center = [0.0, 0.1]
mass = 1.0
)";

const std::string accelerometer = R"(
[[sensors]]
name = "top"
body = "block"
point = [0.25, 0.1]
lowpass_hz = 100.0
)";

const std::string lvdt = R"(
[[sensors]]
name = "slip"
kind = "relative"
body = "block"
point = [-0.25, -0.1]
body2 = "table"
point2 = [-0.25, 0.1]
)";

std::string error_of(const std::string& name, const std::string& text) { return testing::scenario_error("sensor-keys", name, text); }

std::string replace(const std::string& text, const std::string& from, const std::string& to) {
    return testing::replace_once(text, from, to);
}

TEST(SensorKeys, ReadsPointAndRelativeSensors) {
    const LoadedScenario s = load_scenario(write("valid", base + accelerometer + lvdt), {});
    const auto& sensors = s.measurements.sensors;
    ASSERT_EQ(sensors.size(), 2u);
    EXPECT_EQ(sensors[0].name, "top");
    EXPECT_EQ(sensors[0].kind, SensorKind::point);
    EXPECT_EQ(sensors[0].body, s.world.body_id("block"));
    EXPECT_DOUBLE_EQ(sensors[0].point_m.x, 0.25);   // on the corner: the outline counts as inside
    EXPECT_DOUBLE_EQ(sensors[0].lowpass_hz, 100.0);
    EXPECT_EQ(sensors[0].order, 4);
    EXPECT_EQ(sensors[1].kind, SensorKind::relative);
    EXPECT_EQ(sensors[1].body2, s.world.body_id("table"));
    EXPECT_DOUBLE_EQ(sensors[1].lowpass_hz, 0.0);
    // Two bodies: every touching pair is followed by default ("auto").
    EXPECT_TRUE(s.measurements.interfaces.all);
}

TEST(SensorKeys, UnknownBodyNamesTheSensorAndSuggests) {
    const std::string m = error_of("unknown", base + replace(accelerometer, "body = \"block\"", "body = \"blok\""));
    expect_contains(m, "blockdem-sensor-keys-unknown.toml:");
    expect_contains(m, "key 'sensors.top.body'");
    expect_contains(m, "no body is named 'blok' (did you mean 'block'?)");
}

TEST(SensorKeys, PointOutsideTheBodyIsRefusedWithItsExtent) {
    const std::string m = error_of("outside", base + replace(accelerometer, "point = [0.25, 0.1]", "point = [0.0, 0.3]"));
    expect_contains(m, "key 'sensors.top.point'");
    expect_contains(m, "lies outside body 'block'");
    expect_contains(m, "y from -0.1 to 0.1 m");
    const std::string m2 = error_of("outside2", base + replace(lvdt, "point2 = [-0.25, 0.1]", "point2 = [-0.25, 0.2]"));
    expect_contains(m2, "key 'sensors.slip.point2'");
    expect_contains(m2, "lies outside body 'table'");
}

TEST(SensorKeys, CutOffAboveNyquistOfTheStepIsRefused) {
    const std::string m = error_of("nyquist", base + replace(accelerometer, "lowpass_hz = 100.0", "lowpass_hz = 6000.0"));
    expect_contains(m, "key 'sensors.top.lowpass_hz'");
    expect_contains(m, "Nyquist frequency of the time step, 1/(2 dt) = 5000 Hz");
    const std::string order = error_of("order", base + replace(accelerometer, "lowpass_hz = 100.0", "order = 2"));
    expect_contains(order, "key 'sensors.top.order'");
    expect_contains(order, "give lowpass_hz");
}

TEST(SensorKeys, RelativeKeysNeedKindAndDuplicatesAreRefused) {
    const std::string m = error_of("kind", base + replace(lvdt, "kind = \"relative\"\n", ""));
    expect_contains(m, "key 'sensors.slip.body2'");
    expect_contains(m, "kind = \"relative\"");
    const std::string twice = error_of("twice", base + accelerometer + accelerometer);
    expect_contains(twice, "two sensors are named 'top'");
    const std::string typo = error_of("typo", base + replace(accelerometer, "lowpass_hz", "lowpas_hz"));
    expect_contains(typo, "sensors.top.lowpas_hz");
}

TEST(SensorKeys, InterfacesSelection) {
    const LoadedScenario none = load_scenario(write("none", base + "[output]\ninterfaces = \"none\"\n"), {});
    EXPECT_FALSE(none.measurements.interfaces.any());
    const LoadedScenario named = load_scenario(write("named", base + "[output]\ninterfaces = [[\"block\", \"table\"]]\n"), {});
    ASSERT_EQ(named.measurements.interfaces.named.size(), 1u);
    EXPECT_FALSE(named.measurements.interfaces.all);
    EXPECT_EQ(named.measurements.interfaces.named[0].first, named.world.body_id("block"));
    const std::string m = error_of("badpair", base + "[output]\ninterfaces = [[\"block\", \"tabel\"]]\n");
    expect_contains(m, "key 'output.interfaces'");
    expect_contains(m, "no body is named 'tabel' (did you mean 'table'?)");
    const std::string mode = error_of("badmode", base + "[output]\ninterfaces = \"some\"\n");
    expect_contains(mode, "key 'output.interfaces'");
}

}  // namespace
}  // namespace blockdem
