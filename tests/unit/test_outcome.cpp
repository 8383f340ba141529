// The outcome rule of world/outcome.hpp on hand-made records: each word, the order in which they
// apply, the carried fall, what does not count as a fall, and the collapse summary.
#include <gtest/gtest.h>

#include "world/outcome.hpp"

namespace blockdem {
namespace {

// A dynamic 0.9 m tall drum of 1000 kg held up by body 0 (the table) and touching it.
BodyRecord drum(std::vector<std::uint32_t> supporters = {0}) {
    BodyRecord r;
    r.dynamic = true;
    r.mass_kg = 1000.0;
    r.height_m = 0.9;
    r.supporters = std::move(supporters);
    r.touches_a_supporter = true;
    return r;
}

BodyRecord table() { return BodyRecord{}; }  // not dynamic

// Let go of its supporters at t_s and dropped drop_m.
BodyRecord fallen(BodyRecord r, double t_s, double drop_m) {
    r.touches_a_supporter = false;
    r.support_lost_time_s = t_s;
    r.drop_m = drop_m;
    r.drop_time_s = t_s + 0.3;
    r.final_position_m = {2.6, 0.45};
    return r;
}

Outcome outcome_of(const BodyRecord& r) { return classify_outcomes({table(), r}, {})[1].outcome; }

TEST(Outcome, EachWord) {
    EXPECT_EQ(outcome_of(drum()), Outcome::stable);
    BodyRecord r = drum();
    r.rocked = true;
    r.rocking_time_s = 1.0;
    EXPECT_EQ(outcome_of(r), Outcome::rocked);
    r.slid = true;
    r.sliding_time_s = 0.5;
    EXPECT_EQ(outcome_of(r), Outcome::rocked_and_slid);
    EXPECT_EQ(classify_outcomes({table(), r}, {})[1].time_s, 0.5);  // the earlier of the two
    r.rocked = false;
    EXPECT_EQ(outcome_of(r), Outcome::slid);
    r.overturned = true;
    r.overturning_time_s = 3.0;
    EXPECT_EQ(outcome_of(r), Outcome::overturned);
    EXPECT_TRUE(is_failure(Outcome::overturned));
    EXPECT_FALSE(is_failure(Outcome::rocked_and_slid));
    EXPECT_STREQ(to_string(Outcome::left_model), "left_model");
}

TEST(Outcome, DrumThatLeftItsSupporterAndCameDownFellEvenUpright) {
    // The top drum: off the column, 1.8 m down, upright 2.6 m away; not overturned.
    BodyRecord r = fallen(drum({1}), 4.0, 1.8);
    r.slid = r.rocked = true;
    const auto out = classify_outcomes({table(), drum(), r}, {});
    EXPECT_EQ(out[2].outcome, Outcome::fell);
    EXPECT_DOUBLE_EQ(out[2].time_s, 4.0);
    EXPECT_DOUBLE_EQ(out[2].rest_position_m.x, 2.6);
    EXPECT_TRUE(out[2].at_rest);
    EXPECT_TRUE(is_failure(out[2].outcome));
    // Fell comes before overturned: a drum that tumbled off and lies on its side fell.
    r.overturned = true;
    EXPECT_EQ(classify_outcomes({table(), drum(), r}, {})[2].outcome, Outcome::fell);
}

TEST(Outcome, LettingGoWithoutComingDownIsNotAFall) {
    // A brick that slid along its course onto the next brick: no supporter of the start, no drop.
    EXPECT_EQ(outcome_of(fallen(drum(), 2.0, 0.01)), Outcome::stable);
    // A drum in the air at the end of a rocking impact (still above its start) did not fall.
    EXPECT_EQ(outcome_of(fallen(drum(), 2.0, -0.05)), Outcome::stable);
    // The drop threshold is a fraction of the body's own height (0.5 x 0.9 m by default).
    EXPECT_EQ(outcome_of(fallen(drum(), 2.0, 0.44)), Outcome::stable);
    EXPECT_EQ(outcome_of(fallen(drum(), 2.0, 0.46)), Outcome::fell);
    OutcomeThresholds strict;
    strict.fall_drop_ratio = 0.6;
    EXPECT_EQ(classify_outcomes({table(), fallen(drum(), 2.0, 0.5)}, strict)[1].outcome, Outcome::stable);
    // A body with no supporters (in flight at the start) cannot fall.
    EXPECT_EQ(outcome_of(fallen(drum({}), 2.0, 1.0)), Outcome::stable);
}

TEST(Outcome, StillMovingAtTheEndIsFellButNotAtRest) {
    BodyRecord r = fallen(drum(), 2.0, 1.0);
    r.at_rest = false;
    const auto out = classify_outcomes({table(), r}, {});
    EXPECT_EQ(out[1].outcome, Outcome::fell);
    EXPECT_FALSE(out[1].at_rest);
}

TEST(Outcome, CarriedDownByAFallingSupporter) {
    // Drum 2 rides drum 1 off the column: it still touches drum 1, but drum 1 fell and drum 2
    // dropped as far. It fell, from when drum 1 let go.
    BodyRecord d1 = fallen(drum({0}), 3.0, 0.9);
    BodyRecord d2 = drum({1});
    d2.drop_m = 1.0;
    d2.drop_time_s = 3.5;
    d2.final_position_m = {1.0, 0.3};
    const auto out = classify_outcomes({table(), d1, d2}, {});
    EXPECT_EQ(out[2].outcome, Outcome::fell);
    EXPECT_DOUBLE_EQ(out[2].time_s, 3.5);
    EXPECT_DOUBLE_EQ(out[2].failure_time_s, 3.0);
    // Without the drop it stayed where it was (held up by something else): not a fall.
    d2.drop_m = 0.1;
    EXPECT_EQ(classify_outcomes({table(), d1, d2}, {})[2].outcome, Outcome::stable);
    // Passed up a stack whichever order the ids are in.
    BodyRecord top = drum({2});
    top.drop_m = 1.0;
    d2.drop_m = 1.0;
    d2.supporters = {3};
    BodyRecord bottom = fallen(drum({0}), 1.0, 1.0);
    const auto stack = classify_outcomes({table(), top, d2, bottom}, {});
    EXPECT_EQ(stack[1].outcome, Outcome::fell);
    EXPECT_EQ(stack[2].outcome, Outcome::fell);
}

TEST(Outcome, LeftTheModelComesFirst) {
    BodyRecord r = fallen(drum(), 2.0, 5.0);
    r.overturned = true;
    r.left_model = true;
    r.left_model_time_s = 2.6;
    r.left_model_position_m = {3.0, -2.0};
    const auto out = classify_outcomes({table(), r}, {});
    EXPECT_EQ(out[1].outcome, Outcome::left_model);
    EXPECT_DOUBLE_EQ(out[1].time_s, 2.6);
    EXPECT_DOUBLE_EQ(out[1].failure_time_s, 2.0);   // it started to go when it let go
    EXPECT_DOUBLE_EQ(out[1].rest_position_m.y, -2.0);
}

TEST(Outcome, CollapseSummaryOfAColumn) {
    BodyRecord d0 = drum({0});                 // rocked in place
    d0.rocked = true;
    d0.rocking_time_s = 1.0;
    d0.final_displacement_m = 0.05;
    BodyRecord d1 = drum({1});                 // overturned on the column at 4 s
    d1.overturned = true;
    d1.overturning_time_s = 4.0;
    d1.final_displacement_m = 0.2;
    BodyRecord d2 = fallen(drum({2}), 3.0, 1.8);  // fell first, 2.6 m away
    d2.final_displacement_m = 3.2;
    d2.mass_kg = 500.0;
    const std::vector<BodyRecord> records{table(), d0, d1, d2};
    const auto outcomes = classify_outcomes(records, {});
    const CollapseSummary c = summarize_collapse("column", {1, 2, 3}, records, outcomes, {});
    EXPECT_EQ(c.blocks, 3u);
    EXPECT_EQ(c.fell, 1u);
    EXPECT_EQ(c.overturned, 1u);
    EXPECT_EQ(c.left_model, 0u);
    EXPECT_NEAR(c.displaced_mass_fraction, 500.0 / 2500.0, 1e-12);  // only d2 beyond 0.45 m
    EXPECT_EQ(c.first_to_go, 3);
    EXPECT_DOUBLE_EQ(c.first_to_go_time_s, 3.0);
    OutcomeThresholds loose;
    loose.displaced_ratio = 0.1;   // 9 cm: d1's 0.2 m now counts
    EXPECT_NEAR(summarize_collapse("column", {1, 2, 3}, records, outcomes, loose).displaced_mass_fraction, 1500.0 / 2500.0, 1e-12);
    const CollapseSummary none = summarize_collapse("one", {1}, records, outcomes, {});
    EXPECT_EQ(none.first_to_go, -1);
}

}  // namespace
}  // namespace blockdem
