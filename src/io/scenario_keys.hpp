#pragma once
// Scenario keys that read the same in two and three dimensions (io/scenario.cpp defines them,
// io/scenario_3d.cpp reads 3-D scenarios with them): the run's time keys, the contact law's
// parameters, angles given in rad or deg, and one component of the table's motion. Their errors
// are the same words in both dimensions.
#include <filesystem>
#include <optional>
#include <string>

#include "io/toml_reader.hpp"
#include "laws/contact_parameters.hpp"
#include "motion/table_motion.hpp"
#include "world/model.hpp"

namespace blockdem {

/// [simulation]'s keys of the run itself, the same in both dimensions: duration, dt, dt_safety,
/// output_interval, max_energy_error, max_overlap.
void read_run_keys(TableReader& t, SimulationSettings& s);

/// The scenario's `title` and `description`, which the report prints: each a string when given
/// (title = 5 was accepted and shown as "5").
void read_scenario_labels(TableReader& top);

/// Refuses a model without a dynamic body (every body fixed or driven: nothing would move, and a
/// run of it reported nothing), naming the file and the counts.
void check_some_body_moves(const std::string& file, std::size_t dynamic_bodies, std::size_t fixed_bodies,
                           std::size_t driven_bodies);

/// A body's `name`: one plain word (letters, digits, '_' or '-'), as it heads CSV columns and is
/// a path segment of --set.
std::string read_body_name(TableReader& t);

/// The contact keys of one table ([contact] or a pair) on top of base: kn, ks, mu or
/// friction_deg, e (with e_meaning) or h_n, h_s, termination, stiffness and the joint keys.
/// require_mu, require_stiffness: those keys must be present. base_meaning: e_meaning's default.
ContactParameters read_contact_parameters(TableReader& t, const ContactParameters& base, bool require_mu,
                                          bool require_stiffness, const std::string& base_meaning = "paper");

/// An angle given as `base` [rad] or `base`_deg [deg] (not both); nullopt when neither.
std::optional<double> read_angle(TableReader& t, const std::string& base);

/// One component of the table's motion (type = sine, one_sine, one_cosine, ricker, csv, series,
/// record, synthetic or none; docs/scenario.md); file names relative to scenario_dir. A peak
/// acceleration above max_table_acceleration_m_s2 (motion/table_motion.hpp) is refused at the key that sets its size.
ComponentMotion read_component(TableReader t, const std::filesystem::path& scenario_dir);

}  // namespace blockdem
