#include "world/outcome.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace blockdem {

const char* to_string(Outcome outcome) {
    switch (outcome) {
        case Outcome::stable: return "stable";
        case Outcome::rocked: return "rocked";
        case Outcome::slid: return "slid";
        case Outcome::rocked_and_slid: return "rocked_and_slid";
        case Outcome::overturned: return "overturned";
        case Outcome::fell: return "fell";
        case Outcome::left_model: return "left_model";
    }
    return "?";
}

bool is_failure(Outcome outcome) {
    return outcome == Outcome::overturned || outcome == Outcome::fell || outcome == Outcome::left_model;
}

namespace {

bool dropped_far(const BodyRecord& r, const OutcomeThresholds& t) {
    return r.drop_m > t.fall_drop_ratio * r.height_m;
}

// The outcome from the body's own record; `fell` here only for a body that let go of its own
// supporters (the carried case needs the others' outcomes: classify_outcomes).
ClassifiedOutcome own_outcome(const BodyRecord& r, const OutcomeThresholds& t) {
    ClassifiedOutcome o;
    if (!r.dynamic) return o;
    if (r.left_model) {
        o.outcome = Outcome::left_model;
        o.time_s = r.left_model_time_s;
        o.failure_time_s = r.support_lost_time_s >= 0.0 ? r.support_lost_time_s : r.left_model_time_s;
        o.rest_position_m = r.left_model_position_m;
        o.at_rest = false;
        return o;
    }
    if (!r.supporters.empty() && !r.touches_a_supporter && dropped_far(r, t)) {
        o.outcome = Outcome::fell;
        o.time_s = r.support_lost_time_s >= 0.0 ? r.support_lost_time_s : r.drop_time_s;
        o.failure_time_s = o.time_s;
        o.rest_position_m = r.final_position_m;
        o.at_rest = r.at_rest;
        return o;
    }
    if (r.overturned) {
        o.outcome = Outcome::overturned;
        o.time_s = o.failure_time_s = r.overturning_time_s;
        return o;
    }
    if (r.rocked && r.slid) {
        o.outcome = Outcome::rocked_and_slid;
        o.time_s = std::min(r.rocking_time_s, r.sliding_time_s);
    } else if (r.rocked) {
        o.outcome = Outcome::rocked;
        o.time_s = r.rocking_time_s;
    } else if (r.slid) {
        o.outcome = Outcome::slid;
        o.time_s = r.sliding_time_s;
    }
    return o;
}

bool gone(Outcome o) { return o == Outcome::fell || o == Outcome::left_model; }

}  // namespace

std::vector<std::string> untouched_body_warnings(const std::vector<BodyRecord>& records, const std::vector<std::string>& names,
                                                 double duration_s) {
    // Named one by one up to a few, then counted (a packing poured from above has thousands).
    constexpr std::size_t named_at_most = 10;
    std::vector<std::string> warnings;
    const auto name_each = [&](auto is_one, auto warning, const char* more) {
        std::size_t count = 0;
        for (std::size_t i = 0; i < records.size(); ++i) {
            if (!records[i].dynamic || records[i].left_model || !is_one(records[i])) continue;
            if (++count <= named_at_most) warnings.push_back(warning(names[i]));
        }
        if (count > named_at_most) warnings.push_back(fmt::format("... and {} more bodies {} in the run", count - named_at_most, more));
    };
    name_each([](const BodyRecord& r) { return !r.touched_a_body; },
              [&](const std::string& name) {
                  return fmt::format(
                      "body '{}' touched no other body in the run's {:g} s: it was in free flight (from the start, or "
                      "until the run ended before the weight of the bodies below reached it), so its outcome says "
                      "nothing of its stability; check its position (blockdem check lists the bodies touching nothing "
                      "at the start)",
                      name, duration_s);
              },
              "touched no other body");
    name_each([](const BodyRecord& r) { return r.touched_a_body && !r.rested_on_ground; },
              [&](const std::string& name) {
                  return fmt::format(
                      "body '{}' touched other bodies but never rested, directly or through them, on a fixed or driven "
                      "body in the run's {:g} s: it was in free flight with them, so its outcome says nothing of its "
                      "stability; check the group's position",
                      name, duration_s);
              },
              "rested on no fixed or driven body");
    return warnings;
}

std::vector<ClassifiedOutcome> classify_outcomes(const std::vector<BodyRecord>& records, const OutcomeThresholds& thresholds) {
    std::vector<ClassifiedOutcome> out(records.size());
    for (std::size_t i = 0; i < records.size(); ++i) out[i] = own_outcome(records[i], thresholds);
    // Carried down: a body whose supporters all fell or left, and that dropped as far itself,
    // fell with them (the top drum riding the drum below it off the column). Repeated until
    // nothing changes, since a fall can pass up a stack; each pass only adds falls, so at most
    // one pass per body.
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t i = 0; i < records.size(); ++i) {
            const BodyRecord& r = records[i];
            if (!r.dynamic || gone(out[i].outcome) || r.supporters.empty() || !dropped_far(r, thresholds)) continue;
            const bool all_gone = std::all_of(r.supporters.begin(), r.supporters.end(), [&](std::uint32_t s) {
                return s < out.size() && gone(out[s].outcome);
            });
            if (!all_gone) continue;
            double carried_from_s = -1.0;   // when the first of its supporters started to go
            for (std::uint32_t s : r.supporters)
                if (carried_from_s < 0.0 || out[s].failure_time_s < carried_from_s) carried_from_s = out[s].failure_time_s;
            out[i].outcome = Outcome::fell;
            out[i].time_s = r.drop_time_s;
            out[i].failure_time_s = carried_from_s >= 0.0 ? carried_from_s : r.drop_time_s;
            out[i].rest_position_m = r.final_position_m;
            out[i].at_rest = r.at_rest;
            changed = true;
        }
    }
    return out;
}

CollapseSummary summarize_collapse(const std::string& group, const std::vector<std::uint32_t>& members,
                                   const std::vector<BodyRecord>& records, const std::vector<ClassifiedOutcome>& outcomes,
                                   const OutcomeThresholds& thresholds) {
    CollapseSummary c;
    c.group = group;
    double mass_kg = 0.0;
    double displaced_kg = 0.0;
    for (std::uint32_t i : members) {
        const BodyRecord& r = records[i];
        if (!r.dynamic) continue;
        ++c.blocks;
        const Outcome o = outcomes[i].outcome;
        c.fell += o == Outcome::fell ? 1 : 0;
        c.overturned += o == Outcome::overturned ? 1 : 0;
        c.left_model += o == Outcome::left_model ? 1 : 0;
        mass_kg += r.mass_kg;
        // A body that left the model is displaced however far it had got when it was taken out.
        if (o == Outcome::left_model || r.final_displacement_m > thresholds.displaced_ratio * r.height_m)
            displaced_kg += r.mass_kg;
        const double t = outcomes[i].failure_time_s;
        if (is_failure(o) && t >= 0.0 && (c.first_to_go < 0 || t < c.first_to_go_time_s)) {
            c.first_to_go = i;
            c.first_to_go_time_s = t;
        }
    }
    c.displaced_mass_fraction = mass_kg > 0.0 ? displaced_kg / mass_kg : 0.0;
    return c;
}

std::vector<CollapseSummary> summarize_collapse_by_group(const std::vector<std::string>& group_of_body,
                                                         const std::vector<BodyRecord>& records,
                                                         const std::vector<ClassifiedOutcome>& outcomes,
                                                         const OutcomeThresholds& thresholds) {
    std::vector<std::string> groups;
    std::vector<std::vector<std::uint32_t>> members;
    std::vector<std::uint32_t> all;
    for (std::uint32_t i = 0; i < records.size(); ++i) {
        if (!records[i].dynamic) continue;
        all.push_back(i);
        if (i >= group_of_body.size() || group_of_body[i].empty()) continue;
        const auto found = std::find(groups.begin(), groups.end(), group_of_body[i]);
        if (found == groups.end()) {
            groups.push_back(group_of_body[i]);
            members.push_back({i});
        } else {
            members[static_cast<std::size_t>(found - groups.begin())].push_back(i);
        }
    }
    std::vector<CollapseSummary> out;
    for (std::size_t g = 0; g < groups.size(); ++g)
        out.push_back(summarize_collapse(groups[g], members[g], records, outcomes, thresholds));
    out.push_back(summarize_collapse("all", all, records, outcomes, thresholds));
    return out;
}

}  // namespace blockdem
