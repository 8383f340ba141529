// The 3-D contact table's history carry (contact/contact_table_3d.hpp): carried run by run, each
// run found in last step's table from a hint (as the step does it, in parallel), it gives each
// point the history of the point with its key, and a new point none, as one merge of the whole
// table does; whatever the hint.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "contact/contact_table_3d.hpp"

namespace blockdem {
namespace {

// A table of pairs of bodies with a few points each, sorted by key, the history a tag of the key.
std::vector<ContactPoint3d> random_table(std::mt19937& random, int bodies, int pairs) {
    std::uniform_int_distribution<int> body(0, bodies - 1), features(0, 5);
    std::vector<ContactPoint3d> table;
    for (int k = 0; k < pairs; ++k) {
        const auto a = static_cast<std::uint32_t>(body(random));
        const auto b = static_cast<std::uint32_t>(body(random));
        if (a == b) continue;
        for (int f = features(random); f >= 0; --f) {
            ContactPoint3d p;
            p.key = {std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(features(random)),
                     static_cast<std::uint32_t>(features(random))};
            table.push_back(p);
        }
    }
    std::sort(table.begin(), table.end(), [](const auto& x, const auto& y) { return x.key < y.key; });
    table.erase(std::unique(table.begin(), table.end(), [](const auto& x, const auto& y) { return x.key == y.key; }),
                table.end());
    return table;
}

double tag(const ContactKey3d& k) { return 1e6 * k.body_a + 1e3 * k.body_b + 10.0 * k.feature_a + k.feature_b + 1.0; }

TEST(ContactTable3d, RunsCarriedFromAnyHintGiveTheWholeTablesMerge) {
    std::mt19937 random(5);
    int kept = 0, born = 0;
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<ContactPoint3d> previous = random_table(random, 30, 200);
        for (ContactPoint3d& p : previous) p.normal_dashpot_n = tag(p.key);
        const std::vector<ContactPoint3d> fresh = random_table(random, 30, 200);
        std::vector<ContactPoint3d> whole = fresh;
        carry_history(previous, whole);
        // Runs of one pair of bodies each, with hints near, far below, far above and past the end.
        std::vector<ContactPoint3d> runs = fresh;
        for (std::size_t first = 0; first < runs.size();) {
            std::size_t end = first + 1;
            while (end < runs.size() && runs[end].key.body_a == runs[first].key.body_a &&
                   runs[end].key.body_b == runs[first].key.body_b)
                ++end;
            const std::size_t hints[] = {first, 0, previous.size(), previous.size() + 7, first / 3, first * 2};
            carry_history(previous, &runs[first], end - first, hints[(first + trial) % 6]);
            first = end;
        }
        ASSERT_EQ(whole.size(), runs.size());
        for (std::size_t i = 0; i < whole.size(); ++i) {
            EXPECT_EQ(whole[i].normal_dashpot_n, runs[i].normal_dashpot_n) << "point " << i;
            const bool was_there = std::any_of(previous.begin(), previous.end(),
                                               [&](const ContactPoint3d& p) { return p.key == whole[i].key; });
            EXPECT_EQ(whole[i].normal_dashpot_n, was_there ? tag(whole[i].key) : 0.0);
            (was_there ? kept : born) += 1;
        }
    }
    EXPECT_GT(kept, 500);
    EXPECT_GT(born, 500);
}

// The step's hint: where last step's pair of the same rank began, which is a run's first point
// (hint_starts_a_run); that pair is the run's own, or another, below or above it, or none.
TEST(ContactTable3d, RunsCarriedFromRunStartsGiveTheWholeTablesMerge) {
    std::mt19937 random(7);
    const auto run_starts = [](const std::vector<ContactPoint3d>& table) {
        std::vector<std::size_t> starts;
        for (std::size_t i = 0; i < table.size(); ++i)
            if (i == 0 || table[i].key.body_a != table[i - 1].key.body_a ||
                table[i].key.body_b != table[i - 1].key.body_b)
                starts.push_back(i);
        return starts;
    };
    int found_at_hint = 0;
    for (int trial = 0; trial < 50; ++trial) {
        // Two tables of few bodies (12), so that they share most pairs, as two steps do.
        std::vector<ContactPoint3d> previous = random_table(random, 12, 60);
        for (ContactPoint3d& p : previous) p.normal_dashpot_n = tag(p.key);
        const std::vector<ContactPoint3d> fresh = random_table(random, 12, 60);
        std::vector<ContactPoint3d> whole = fresh;
        carry_history(previous, whole);
        const std::vector<std::size_t> previous_starts = run_starts(previous);
        const std::vector<std::size_t> starts = run_starts(fresh);
        std::vector<ContactPoint3d> runs = fresh;
        for (std::size_t rank = 0; rank < starts.size(); ++rank) {
            const std::size_t first = starts[rank];
            const std::size_t end = rank + 1 < starts.size() ? starts[rank + 1] : runs.size();
            if (rank >= previous_starts.size()) {
                carry_history(previous, &runs[first], end - first, first);
                continue;
            }
            const std::size_t hint = previous_starts[rank];
            found_at_hint += previous[hint].key.body_a == runs[first].key.body_a &&
                             previous[hint].key.body_b == runs[first].key.body_b;
            carry_history(previous, &runs[first], end - first, hint, true);
        }
        ASSERT_EQ(whole.size(), runs.size());
        for (std::size_t i = 0; i < whole.size(); ++i)
            EXPECT_EQ(whole[i].normal_dashpot_n, runs[i].normal_dashpot_n) << "point " << i;
    }
    EXPECT_GT(found_at_hint, 20);
}

// The step's straight merge: a run whose pair had a run last step (is_run_of at that run's
// bounds) merged against that run alone by features, with shares that change (the spring scaled
// by w_now / w_before, and dropped where w was 0), gives the whole table's merge to the bit.
TEST(ContactTable3d, RunsMergedAgainstTheirPairsLastRunGiveTheWholeTablesMerge) {
    std::mt19937 random(11);
    std::uniform_int_distribution<int> share_of(0, 3);
    const auto runs_of = [](const std::vector<ContactPoint3d>& table) {
        std::vector<std::pair<std::size_t, std::size_t>> runs;
        for (std::size_t i = 0; i < table.size(); ++i)
            if (i == 0 || table[i].key.body_a != table[i - 1].key.body_a ||
                table[i].key.body_b != table[i - 1].key.body_b)
                runs.emplace_back(i, i + 1);
            else
                runs.back().second = i + 1;
        return runs;
    };
    int straight = 0, searched = 0, scaled = 0;
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<ContactPoint3d> previous = random_table(random, 12, 60);
        for (ContactPoint3d& p : previous) {
            p.normal_dashpot_n = tag(p.key);
            p.shear.spring_n = {tag(p.key), -1.0, 0.5};
            p.stiffness_share = 0.25 * share_of(random);
        }
        std::vector<ContactPoint3d> fresh = random_table(random, 12, 60);
        for (ContactPoint3d& p : fresh) p.stiffness_share = 0.25 * share_of(random);
        std::vector<ContactPoint3d> whole = fresh;
        carry_history(previous, whole);
        const auto last_runs = runs_of(previous);
        std::vector<ContactPoint3d> runs = fresh;
        for (const auto& [first, end] : runs_of(fresh)) {
            // The key copied out: Clang before 16 cannot capture a structured binding.
            const ContactKey3d key = fresh[first].key;
            const auto last = std::find_if(last_runs.begin(), last_runs.end(), [&](const auto& r) {
                return is_run_of(previous, r.first, r.second, key);
            });
            // Another pair's run is not taken for this one's.
            for (const auto& r : last_runs)
                if (previous[r.first].key.body_a != fresh[first].key.body_a ||
                    previous[r.first].key.body_b != fresh[first].key.body_b)
                    ASSERT_FALSE(is_run_of(previous, r.first, r.second, fresh[first].key));
            if (last != last_runs.end()) {
                carry_history_from_run(&previous[last->first], last->second - last->first, &runs[first], end - first);
                ++straight;
            } else {
                carry_history(previous, &runs[first], end - first, first);
                ++searched;
            }
        }
        ASSERT_EQ(whole.size(), runs.size());
        for (std::size_t i = 0; i < whole.size(); ++i) {
            EXPECT_EQ(whole[i].normal_dashpot_n, runs[i].normal_dashpot_n) << "point " << i;
            EXPECT_EQ(whole[i].shear.spring_n.x, runs[i].shear.spring_n.x) << "point " << i;
            EXPECT_EQ(whole[i].shear.spring_n.y, runs[i].shear.spring_n.y) << "point " << i;
            scaled += whole[i].normal_dashpot_n != 0.0 && whole[i].shear.spring_n.y != -1.0;
        }
    }
    EXPECT_GT(straight, 200);
    EXPECT_GT(searched, 20);
    EXPECT_GT(scaled, 100);
}

}  // namespace
}  // namespace blockdem
