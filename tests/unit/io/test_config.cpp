// SPDX-License-Identifier: MIT
// Case-file loading: hostile input gets one clear error naming key, value, allowed range and
// file:line; the derived numbers through the loader; the time-step guard (T-U7).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <vector>

#include "io/config/load.hpp"
#include "io/config/schema.hpp"
#include "io/report_json.hpp"
#include "scenario/setup.hpp"

namespace silodem {
namespace {

std::string base() {
  std::ifstream in(std::string(SILODEM_SOURCE_DIR) + "/tests/data/base.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// True if some line of `text` consists of exactly these whitespace-separated words. (Not
// std::regex: g++ 12's <regex> trips -Wmaybe-uninitialized in the sanitizer build.)
bool has_line(const std::string& text, const std::vector<std::string>& words) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream in(line);
    std::vector<std::string> got;
    for (std::string w; in >> w;) got.push_back(w);
    if (got == words) return true;
  }
  return false;
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  if (pos == std::string::npos) throw std::logic_error("test setup: '" + from + "' not found");
  return s.replace(pos, from.size(), to);
}

int line_of(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  return 1 + int(std::count(text.begin(), text.begin() + long(pos), '\n'));
}

// Loads (and derives and builds, as `run` does) and returns the error message, or "".
std::string error_of(const std::string& text) {
  try {
    const Case c = config::load_case_text(text, "case.toml");
    ContactModel model;
    const CaseReport r = derive_case(c, &model);
    build_simulation(c, r, std::move(model));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& text, const std::string& needle_line,
                  const std::vector<std::string>& parts) {
  const std::string msg = error_of(text);
  ASSERT_FALSE(msg.empty()) << "no error for a case with '" << needle_line << "'";
  EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
  const std::string where = "case.toml:" + std::to_string(line_of(text, needle_line)) + ":";
  EXPECT_NE(msg.find(where), std::string::npos) << "expected " << where << " in: " << msg;
  for (const auto& p : parts)
    EXPECT_NE(msg.find(p), std::string::npos) << "expected '" << p << "' in: " << msg;
}

TEST(Config, BaseCaseLoadsAndDerives) {
  const Case c = config::load_case_text(base(), "case.toml");
  ASSERT_EQ(c.coals.size(), 1u);
  EXPECT_NEAR(c.coals[0].diameter, 2.8e-3, 1e-15);
  EXPECT_NEAR(c.coals[0].cohesion, 670.0, 1e-9);
  const CaseReport r = derive_case(c);
  EXPECT_NEAR(r.coals[0].cohesion_cg / 0.2599, 1.0, 1e-3);
  EXPECT_NEAR(r.coals[0].collision_time / 1.921e-4, 1.0, 1e-3);  // k_n = 1e5 row of 1.4
  EXPECT_NEAR(r.time_step, r.collision_time_min / 50.0, 1e-18);
}

TEST(Config, UnknownKeyWithSuggestion) {
  const std::string t = replace(base(), "moisture_percent = 8.8", "moisture_pecent = 8.8");
  expect_error(t, "moisture_pecent",
               {"coal[0].moisture_pecent", "did you mean 'moisture_percent'"});
}

TEST(Config, UnknownSectionAndLaw) {
  expect_error(replace(base(), "[simulation]", "[simulaton]"), "[simulaton]",
               {"simulaton", "did you mean 'simulation'"});
  const std::string t =
      replace(base(), "law = \"mfix\", friction = 0.6", "law = \"epsdd\", friction = 0.6");
  expect_error(t, "epsdd", {"rolling.law", "epsdd", "did you mean 'epsd'"});
}

TEST(Config, AKeyOfAnotherLawSaysHowToReplaceTheTable) {
  // What `--set ...rolling.law=none` leaves behind: the old law's friction beside the new law.
  const std::string t =
      replace(base(), "law = \"mfix\", friction = 0.6", "law = \"none\", friction = 0.6");
  expect_error(t, "law = \"none\", friction = 0.6",
               {"contact.particle_particle.rolling.friction", "unknown key", "law 'none'",
                "--set 'contact.particle_particle.rolling={ law = \"none\" }'"});
}

TEST(Config, Mfix21RollingLengthInMetres) {
  // The paper's 0.6 read as MFiX 21.3 reads it (a length) loads; beyond 1 m is refused.
  const std::string from = "law = \"mfix\", friction = 0.6";
  const std::string ok = replace(base(), from, "law = \"mfix-21\", length_m = 0.6");
  ContactModel model;
  derive_case(config::load_case_text(ok, "case.toml"), &model);
  EXPECT_EQ(model.pair(0, 0).law_names[2], "mfix-21");
  EXPECT_EQ(model.pair(0, 0).params<RollingMfix21>().length, 0.6);
  expect_error(replace(base(), from, "law = \"mfix-21\", length_m = 1.5"), "length_m = 1.5",
               {"rolling.length_m", "1.5", "[0, 1]"});
}

TEST(Config, MissingRequiredKey) {
  const std::string t = replace(base(), "true_density_kg_m3 = 1567\n", "");
  const std::string msg = error_of(t);
  EXPECT_NE(msg.find("coal[0].true_density_kg_m3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("missing required key"), std::string::npos) << msg;
  EXPECT_NE(msg.find("case.toml:" + std::to_string(line_of(base(), "[[coal]]"))), std::string::npos)
      << msg;
}

TEST(Config, NegativeDiameter) {
  expect_error(replace(base(), "diameter_mm = 2.8", "diameter_mm = -2.8"), "diameter_mm = -2.8",
               {"coal[0].diameter_mm", "-2.8", "(0, 10000]", "mm"});
}

TEST(Config, IntegerTooLargeForADoubleIsOutOfRangeNotACrash) {
  // 7788888888888888888 has no exact double; it once threw bad_optional_access (fuzzer).
  expect_error(
      replace(base(), "bulk_density_kg_m3 = 778", "bulk_density_kg_m3 = 7788888888888888888"),
      "bulk_density_kg_m3 = 7788888888888888888",
      {"bulk_density_kg_m3", "7788888888888888888", "out of range"});
}

TEST(Config, MoistureAtOrAbove100) {
  expect_error(replace(base(), "moisture_percent = 8.8", "moisture_percent = 100"),
               "moisture_percent = 100", {"moisture_percent", "= 100", "[0, 100)", "%"});
}

TEST(Config, BulkDensityAboveTrueDensity) {
  expect_error(replace(base(), "bulk_density_kg_m3 = 778", "bulk_density_kg_m3 = 1600"),
               "bulk_density_kg_m3 = 1600", {"bulk_density_kg_m3", "1600", "1567", "(0, 1567]"});
}

TEST(Config, KBelowOne) {
  expect_error(replace(base(), "k = 3", "k = 0.5"), "k = 0.5",
               {"coarse_graining.k", "0.5", "[1, 100]"});
}

TEST(Config, WrongType) {
  expect_error(replace(base(), "k = 3", "k = \"three\""), "k = \"three\"",
               {"coarse_graining.k", "must be a number"});
}

TEST(Config, OverlappingPlacedParticles) {
  expect_error(replace(base(), "position = [0.02, 0.0, 0.01]", "position = [0.005, 0.0, 0.01]"),
               "position = [0.005", {"particle[1].position", "overlaps particle[0]"});
}

TEST(Config, TU7_TimeStepGuard) {
  // t_col,min here is the k = 3 pair at k_n = 1e5: 1.921e-4 s; t_col / 10 = 1.92e-5 s.
  const std::string too_big =
      replace(base(), "end_time = 0.01", "end_time = 0.01\ntime_step = 2.5e-5");
  expect_error(too_big, "time_step = 2.5e-5",
               {"simulation.time_step", "2.5e-05", "1.921e-05", "t_col"});
  const std::string ok = replace(base(), "end_time = 0.01", "end_time = 0.01\ntime_step = 9.6e-6");
  EXPECT_EQ(error_of(ok), "");  // dt <= t_col / 20 passes
}

TEST(Config, RestitutionPolicyEnergyRefusesPaperValue) {
  const std::string t = replace(base(), "k = 3", "k = 3\nrestitution_policy = \"energy\"");
  expect_error(t, "restitution = 0.1 }", {"restitution", "no real value"});
  const std::string clamped =
      replace(base(), "k = 3", "k = 3\nrestitution_policy = \"energy-clamped\"");
  const Case c = config::load_case_text(clamped, "case.toml");
  const CaseReport r = derive_case(c);
  EXPECT_DOUBLE_EQ(r.coals[0].restitution.value, 0.01);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].find("clamped"), std::string::npos);
}

TEST(Config, TomlSyntaxError) {
  const std::string t = replace(base(), "k = 3", "k = = 3");
  expect_error(t, "k = = 3", {"TOML syntax error"});
}

TEST(Config, DocsMentionEveryLawAndSection) {
  const std::string md = config::markdown();
  for (const char* s : {"[simulation]", "[[coal]]", "linear_history", "epsd", "mfix-like", "box"})
    EXPECT_NE(md.find(s), std::string::npos) << s;
}

// Issue 18, item 1: a key is bound to its member once; the member's initial value is the default.
struct Demo {
  double length = 0.1;  // m
  int count = 3;
  std::string name = "demo";
  double marker = 0.0;  // outside the key's range: "not given"
};

TEST(Config, ABoundKeyTakesItsDefaultFromTheSpecAndShowsItInTheFileUnit) {
  const std::vector<Bound<Demo>> b = {
      bind(Field::number("length_mm", "", "mm", 1e-3).above(0), &Demo::length),
      bind(Field::integer("count", "").at_least(1), &Demo::count),
      bind(Field::text("name", "", {}), &Demo::name),
      bind(Field::number("marker", "").above(0), &Demo::marker),
  };
  ASSERT_TRUE(b[0].field.default_number.has_value());
  EXPECT_NEAR(*b[0].field.default_number, 100.0, 1e-9);  // 0.1 m in mm
  EXPECT_EQ(b[1].field.default_number, 3.0);
  EXPECT_EQ(b[2].field.default_string, "demo");
  EXPECT_FALSE(b[2].field.required);                    // a string with a default may be left out
  EXPECT_FALSE(b[3].field.default_number.has_value());  // 0 is not in (0, inf): shown as "-"

  ParamValues v;  // as the loader gives it: SI values, with which keys were written
  v.numbers = {{"length_mm", 0.25}, {"count", 3.0}, {"marker", 0.0}};
  v.strings = {{"name", "demo"}};
  v.given = {{"length_mm", true}, {"count", false}, {"name", false}, {"marker", false}};
  Demo d;
  d.count = 7;  // a key not given leaves the member as it is
  assign(d, b, v);
  EXPECT_EQ(d.length, 0.25);
  EXPECT_EQ(d.count, 7);
  EXPECT_EQ(d.name, "demo");
}

TEST(Config, AGivenKeyReachesItsMemberAndTheRestKeepTheSpecDefaults) {
  std::ifstream in(std::string(SILODEM_SOURCE_DIR) + "/tests/data/small_silo.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str() + "[probes]\nslab_thickness_mm = 5\nslab_times = [2.0, 0.5]\n";
  const Case c = config::load_case_text(text, "case.toml");
  EXPECT_DOUBLE_EQ(c.probes.slab_thickness, 0.005);                 // mm -> m
  EXPECT_EQ(c.probes.slab_times, (std::vector<double>{0.5, 2.0}));  // sorted by the loader
  const ProbeSpec d;
  EXPECT_EQ(c.probes.every, d.every);
  EXPECT_EQ(c.probes.profile_heights, d.profile_heights);
  EXPECT_DOUBLE_EQ(c.discharge.bin, 0.1);
  EXPECT_DOUBLE_EQ(c.discharge.sink_depth, 0.03);
  EXPECT_EQ(c.discharge.target_fraction, DischargeSpec{}.target_fraction);
  EXPECT_DOUBLE_EQ(c.silo.geometry.outlet_diameter, 0.04);
  EXPECT_EQ(c.silo.geometry.valve_gap, SiloGeometry{}.valve_gap);
  EXPECT_EQ(c.fill.mode, FillMode::Mass);
  EXPECT_DOUBLE_EQ(c.coals[0].sauter_diameter, 0.005);  // not given: the coal's diameter
  EXPECT_EQ(*c.coals[0].cohesion_force_override, 0.0);
  EXPECT_EQ(c.time.threads, 2);
  EXPECT_EQ(c.time.gravity.z, TimeSpec{}.gravity.z);
}

// Two coals: base.toml's Longwanggou and the paper's Indonesian (Table 1), particle 2 of the
// second coal, 50 mm from the first, and `extra` appended (per-coal contact tables).
std::string two_coals(const std::string& extra = {}) {
  std::string t = replace(base(), "[contact.particle_particle]",
                          "[[coal]]\nname = \"Indonesian\"\ndiameter_mm = 3.2\n"
                          "bulk_density_kg_m3 = 728\ntrue_density_kg_m3 = 1268\n"
                          "cohesion_kpa = 0.68\nfriction_angle_deg = 37.2\n"
                          "moisture_percent = 35.1\nheating_value_kcal_kg = 3108\n\n"
                          "[contact.particle_particle]");
  t = replace(t, "coal = \"Longwanggou\"\nposition = [0.02,",
              "coal = \"Indonesian\"\nposition = [0.05,");
  return t + extra;
}

TEST(Config, PerCoalContactValuesReachTheirPairsAndMixForTwoCoals) {
  const std::string over =
      "\n[contact.particle_particle.coal.Indonesian]\n"
      "normal = { stiffness = 4.0e5 }\ntangential = { friction = 0.5 }\n"
      "\n[contact.particle_wall.coal.Indonesian]\ntangential = { friction = 0.3 }\n";
  ContactModel m;
  const Case c = config::load_case_text(two_coals(over), "case.toml");
  const CaseReport r = derive_case(c, &m);
  ASSERT_EQ(m.materials(), 2);
  auto mu = [](const ContactLaw& l) { return l.params<TangentialLinearHistory>().friction; };
  auto kn = [](const ContactLaw& l) { return l.params<NormalLinearSpringDashpot>().stiffness; };
  EXPECT_EQ(mu(m.pair(0, 0)), 0.09);  // Longwanggou keeps the section's values
  EXPECT_EQ(kn(m.pair(0, 0)), 1.0e5);
  EXPECT_EQ(mu(m.pair(1, 1)), 0.5);
  EXPECT_EQ(kn(m.pair(1, 1)), 4.0e5);
  // Two coals: the harmonic mean 2 a b / (a + b) of each number (the default mixing).
  EXPECT_NEAR(mu(m.pair(0, 1)), 2.0 * 0.09 * 0.5 / 0.59, 1e-14);
  EXPECT_NEAR(kn(m.pair(1, 0)), 1.6e5, 1e-9);
  EXPECT_EQ(mu(m.pair(0, 1)), mu(m.pair(1, 0)));
  EXPECT_EQ(mu(m.wall(0)), 0.1);
  EXPECT_EQ(mu(m.wall(1)), 0.3);
  EXPECT_EQ(kn(m.wall(1)), 1.0e5);  // no wall stiffness of its own
  // The stiffer pair sets the time step: t_col = pi / sqrt(k / m_eff (1 - zeta^2)) scales as
  // k^-1/2, so Indonesian-Indonesian at 4e5 is half its t_col at the section's 1e5.
  ContactModel plain;
  const CaseReport r0 = derive_case(config::load_case_text(two_coals(), "case.toml"), &plain);
  EXPECT_NEAR(r.coals[1].collision_time / r0.coals[1].collision_time, 0.5, 1e-12);
  EXPECT_EQ(r.coals[0].collision_time, r0.coals[0].collision_time);
  EXPECT_LT(r.collision_time_min, r0.collision_time_min);
  // `check` lists what each pair kind uses.
  const std::string text = case_report_text(c, r);
  EXPECT_TRUE(has_line(text, {"pair", "Longwanggou-Indonesian", "tangential.friction", "0.152542"}))
      << text;
  EXPECT_TRUE(has_line(text, {"wall", "Indonesian", "tangential.friction", "0.3"})) << text;
  // mixing = "mean": the arithmetic mean.
  const std::string mean = replace(two_coals(over), "[contact.particle_particle]\n",
                                   "[contact.particle_particle]\nmixing = \"mean\"\n");
  ContactModel mm;
  derive_case(config::load_case_text(mean, "case.toml"), &mm);
  EXPECT_NEAR(mu(mm.pair(0, 1)), 0.295, 1e-15);
  EXPECT_NEAR(kn(mm.pair(0, 1)), 2.5e5, 1e-9);
  EXPECT_EQ(mu(mm.pair(1, 1)), 0.5);
}

TEST(Config, PerCoalValuesOfBothCoalsMixKeyByKeyAndStayExactForOneCoal) {
  // Both coals set the friction, each one key more; 0.1 and 0.7 are not exact in binary, so a
  // value passed through a mean of itself (2 x x / (x + x)) could come back changed.
  const std::string tables =
      "\n[contact.particle_particle.coal.Longwanggou]\n"
      "tangential = { friction = 0.1 }\nrolling = { friction = 0.7 }\n"
      "\n[contact.particle_particle.coal.Indonesian]\n"
      "tangential = { friction = 0.3 }\nnormal = { stiffness = 3.0e5 }\n"
      "\n[contact.particle_wall.coal.Longwanggou]\ntangential = { friction = 0.7 }\n";
  auto model = [&](const std::string& mixing) {
    std::string t = two_coals(tables);
    if (!mixing.empty())
      t = replace(t, "[contact.particle_particle]\n",
                  "[contact.particle_particle]\nmixing = \"" + mixing + "\"\n");
    ContactModel m;
    derive_case(config::load_case_text(t, "case.toml"), &m);
    return m;
  };
  auto mu = [](const ContactLaw& l) { return l.params<TangentialLinearHistory>().friction; };
  auto mur = [](const ContactLaw& l) { return l.params<RollingMfix>().friction; };
  auto kn = [](const ContactLaw& l) { return l.params<NormalLinearSpringDashpot>().stiffness; };
  const ContactModel h = model(""), mn = model("min");
  for (const ContactModel* m : {&h, &mn}) {
    EXPECT_EQ(mu(m->pair(0, 0)), 0.1);  // exactly a coal's own value
    EXPECT_EQ(mur(m->pair(0, 0)), 0.7);
    EXPECT_EQ(mu(m->pair(1, 1)), 0.3);
    EXPECT_EQ(mur(m->pair(1, 1)), 0.6);  // the section's
    EXPECT_EQ(mu(m->wall(0)), 0.7);
    EXPECT_EQ(mu(m->wall(1)), 0.1);  // the section's wall friction
  }
  EXPECT_NEAR(mu(h.pair(0, 1)), 0.15, 1e-15);  // 2 / (1/0.1 + 1/0.3)
  EXPECT_NEAR(mur(h.pair(1, 0)), 2.0 / (1.0 / 0.7 + 1.0 / 0.6), 1e-15);
  EXPECT_NEAR(kn(h.pair(0, 1)), 1.5e5, 1e-9);  // 2 / (1/1e5 + 1/3e5)
  EXPECT_EQ(mu(mn.pair(0, 1)), 0.1);
  EXPECT_EQ(mur(mn.pair(0, 1)), 0.6);
  EXPECT_EQ(kn(mn.pair(1, 0)), 1.0e5);
}

TEST(Config, PerCoalContactValuesFromTheCommandLine) {
  const std::string path = ::testing::TempDir() + "/per_coal.toml";
  {
    std::ofstream out(path);
    out << two_coals();
  }
  ContactModel m;
  derive_case(config::load_case_file(
                  path, {"contact.particle_particle.coal.Indonesian.tangential.friction=0.5"}),
              &m);
  EXPECT_EQ(m.pair(1, 1).params<TangentialLinearHistory>().friction, 0.5);
  EXPECT_EQ(m.pair(0, 0).params<TangentialLinearHistory>().friction, 0.09);
}

TEST(Config, PerCoalContactValuesRefuseWhatCannotDifferPerCoal) {
  const std::string head = "\n[contact.particle_particle.coal.Indonesian]\n";
  expect_error(two_coals("\n[contact.particle_particle.coal.Indonesain]\n"
                         "tangential = { friction = 0.5 }\n"),
               "[contact.particle_particle.coal.Indonesain]",
               {"contact.particle_particle.coal.Indonesain", "not a [[coal]] name",
                "did you mean 'Indonesian'"});
  expect_error(two_coals(head + "rolling = { law = \"epsd\", friction = 0.3 }\n"),
               "rolling = { law = \"epsd\"",
               {"contact.particle_particle.coal.Indonesian.rolling.law", "cannot change the law",
                "\"mfix\""});
  expect_error(
      two_coals(head + "tangential = { friction = -0.5 }\n"), "friction = -0.5",
      {"contact.particle_particle.coal.Indonesian.tangential.friction", "-0.5", "out of range"});
  expect_error(
      two_coals(head + "cohesion = { pair_rule = \"min\" }\n"), "pair_rule = \"min\"",
      {"contact.particle_particle.coal.Indonesian.cohesion.pair_rule", "cannot differ per coal"});
  expect_error(
      replace(two_coals(head + "rolling = { friction = 0.3 }\n"),
              "rolling    = { law = \"mfix\", friction = 0.6 }", "rolling    = { law = \"none\" }"),
      "rolling = { friction = 0.3 }",
      {"contact.particle_particle.coal.Indonesian.rolling", "\"none\"", "no numbers"});
  // A per-coal value that does not fit the section's other values is that coal's error, found
  // in its own contacts before any pair of two coals (Luding: unloading above loading stiffness).
  const std::string luding =
      "normal     = { law = \"luding\", stiffness = 1.0e5, unloading_stiffness = 1.5e5, "
      "adhesion_stiffness = 0.0, restitution = 0.1 }";
  expect_error(replace(two_coals("\n[contact.particle_particle.coal.Longwanggou]\n"
                                 "normal = { restitution = 0.5 }\n" +
                                 head + "normal = { stiffness = 1.0e6 }\n"),
                       "normal     = { law = \"linear_spring_dashpot\", stiffness = 1.0e5, "
                       "restitution = 0.1 }",
                       luding),
               "unloading_stiffness = 1.5e5",
               {"contact.particle_particle.coal.Indonesian.normal.unloading_stiffness",
                "must be larger than 'stiffness' (1000000"});
  expect_error(two_coals(head + "tangentail = { friction = 0.5 }\n"), "tangentail",
               {"unknown slot", "did you mean 'tangential'"});
  expect_error(replace(two_coals(), "[contact.particle_particle]\n",
                       "[contact.particle_particle]\nmixing = \"geometric\"\n"),
               "mixing = \"geometric\"", {"mixing", "geometric", "harmonic, mean, min"});
  expect_error(replace(two_coals(), "[contact.particle_wall]\n",
                       "[contact.particle_wall]\nmixing = \"mean\"\n"),
               "mixing = \"mean\"", {"contact.particle_wall.mixing", "unknown key"});
}

// Behaviour: each coal rests on the floor on its own wall stiffness. A sphere at rest on a plane
// under gravity compresses a linear spring by m g / k_n (force balance; cohesion off).
TEST(Config, EachCoalRestsOnItsOwnWallStiffness) {
  std::string t =
      two_coals("\n[contact.particle_wall.coal.Indonesian]\nnormal = { stiffness = 1.0e3 }\n");
  for (int i = 0; i < 2; ++i)
    t = replace(t, "cohesion   = { law = \"overlap-only\" }", "cohesion   = { law = \"none\" }");
  const Case c = config::load_case_text(t, "case.toml");
  ContactModel model;
  const CaseReport r = derive_case(c, &model);
  auto sim = build_simulation(c, r, std::move(model));
  sim->run_until(0.5);
  const ParticleStore& p = sim->particles();
  ASSERT_EQ(p.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const double k = p.material[i] == 1 ? 1.0e3 : 1.0e5;
    const double overlap = p.radius[i] - p.x[i].z;
    EXPECT_NEAR(overlap / (p.mass[i] * 9.81 / k), 1.0, 0.01) << "coal " << p.material[i];
  }
}

}  // namespace
}  // namespace silodem
