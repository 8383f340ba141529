#include "io/record_motion_keys.hpp"

namespace blockdem {

// Placeholder so that the scenario parser links; the real reader follows.
AccelerationSeries read_record_motion(TableReader& keys, const std::filesystem::path&) {
    keys.fail("", "type = \"record\" is not available yet in this build");
}

AccelerationSeries read_synthetic_motion(TableReader& keys) {
    keys.fail("", "type = \"synthetic\" is not available yet in this build");
}

}  // namespace blockdem
