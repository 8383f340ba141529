#pragma once
// Shared by the malformed-record tests (test_records_errors.cpp, test_records_limits.cpp): read
// a record file written from text and keep what its InputError says, so that each test file
// checks the parts it is about; and the PEER header the malformed AT2 files start with.
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "records_test_support.hpp"

namespace blockdem::testing {

/// Where an InputError of a record file points, and its message.
struct RecordFailure {
    std::string file;
    int line = 0;
    std::string message;
};

/// The InputError of reading content written as the file name; a test failure (and an empty
/// RecordFailure) when it reads without one.
inline RecordFailure read_failure(const std::string& name, const std::string& content, RecordReadOptions options = {}) {
    const auto path = write_temp_file(name, content);
    try {
        read_ground_motion_record(path, options);
    } catch (const InputError& e) {
        return {e.where().file, e.where().line, e.what()};
    }
    ADD_FAILURE() << name << ": no InputError";
    return {};
}

/// The first three lines of a PEER AT2 file in g; the NPTS line and the values follow.
inline const std::string at2_header =
    "PEER NGA STRONG MOTION DATABASE RECORD\n"
    "Bad Event, 1/2/2003, Bad Station, 90\n"
    "ACCELERATION TIME SERIES IN UNITS OF G\n";

}  // namespace blockdem::testing
