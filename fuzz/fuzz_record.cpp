// Fuzzes one ground-motion record reader (BLOCKDEM_FUZZ_RECORD_FORMAT names it, "auto" detects
// it from the content) through read_ground_motion_record, as `blockdem motion` and a
// type = "record" table motion read a file: once with the file's own units and dt, once with
// units and dt given (plain text needs them), then the intensity measures of what was read.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_workspace.hpp"
#include "motion/intensity_measures.hpp"
#include "motion/records/ground_motion_record.hpp"

namespace {

using namespace blockdem;

void check_record(const std::filesystem::path& file, RecordReadOptions options) {
    options.format = parse_record_format(BLOCKDEM_FUZZ_RECORD_FORMAT);
    const GroundMotionRecord record = read_ground_motion_record(file, options);
    (void)intensity_measures(record.acceleration_m_s2, record.dt_s);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = fuzz::write_input("record", data, size);
    fuzz::expect_input_errors([&] { check_record(file, {}); });
    RecordReadOptions given;
    given.units = "gal";
    given.dt_s = 0.01;
    fuzz::expect_input_errors([&] { check_record(file, given); });
    return 0;
}
