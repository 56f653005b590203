// SPDX-License-Identifier: MIT
// A rigid plate: a movable wall (a plane) and, optionally, particles glued to it (a rough face
// made of the material itself, as the bottom and lid of a shear cell), moving as one body. It is
// driven at a set velocity, or servo-controlled along the wall's normal to hold a set normal
// stress while it moves at a set velocity in the wall's plane. It reports the force the particles
// exert on it, its displacement and its velocity.
//
// Glued particles get zero inverse mass and inertia, so the integrator moves them at the
// velocity the plate gives them and no force changes it; the forces on them are still summed
// (ParticleStore::f), which is how the plate measures its load. Their contacts keep the mass
// and radius they had, so the contact laws see the material they are made of.
//
// advance() is called at the beginning of every step (a Phase::StepBegin hook, add_to()). It
// reads the force of the last force pass, sets the velocity, moves the wall by v dt and gives the
// glued particles v, which the integrator then applies to them: wall and particles stay
// together. The servo law is proportional-integral: the normal speed is
// gain x (e + (1 / integral_time) x integral of e dt), e = target load - load, capped at
// max_speed (the integral stops growing while the cap holds, so it does not wind up). It is stable
// when gain x (c + k dt) < 1, where k and c are the summed stiffness and damping coefficient of the
// plate's contacts: the dashpots answer the plate's own speed at once.
#pragma once
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"

namespace silodem {

class ByteReader;
class ByteWriter;
class Simulation;

struct PlateControl {
  Vec3 velocity;           // m/s: the plate's velocity (with servo: its part in the wall's plane)
  bool servo = false;      // hold `stress` on `area` by moving along the wall's normal
  double stress = 0.0;     // Pa, the compressive normal stress to hold
  double area = 0.0;       // m^2, the area the stress acts on
  double gain = 0.0;       // m/s per N of load error
  double max_speed = 0.0;  // m/s, the servo's largest normal speed (0: no cap)
  // s: the integral action's time (0: proportional only). The proportional servo holds a sample
  // that creeps or dilates at speed v off its target by v / gain; the integral takes that up.
  double integral_time = 0.0;
};

class Plate {
 public:
  // `wall` must be movable (Wall::movable) and a plane; `glued` are particle indices (they may
  // be reordered later: the plate follows their ids).
  Plate(Simulation& sim, std::size_t wall, const std::vector<std::size_t>& glued = {});
  // Glues more particles to the plate (they stop and move with it from the next step).
  void glue(Simulation& sim, const std::vector<std::size_t>& particles);
  void set_control(const PlateControl& c) { control_ = c; }
  const PlateControl& control() const { return control_; }
  void advance(Simulation& sim);
  // Installs advance() as a StepBegin hook of `sim`; the plate must outlive the simulation's run.
  void add_to(Simulation& sim);

  // The force the particles exert on the plate in the last force pass (N): on the wall and on
  // the glued particles from the free ones (the glued particles' contacts among themselves
  // cancel, gravity and external forces on them are left out).
  Vec3 force(const Simulation& sim) const;
  // Compressive load along the wall's normal: -force . n (N; the normal points to the particles).
  double load(const Simulation& sim) const;
  Vec3 displacement() const { return displacement_; }
  Vec3 velocity() const { return velocity_; }
  const Vec3& normal() const { return normal_; }
  std::size_t wall() const { return wall_; }
  const std::vector<std::uint64_t>& glued_ids() const { return ids_; }

  // Checkpoint of the plate and of its wall's position and velocity (the simulation's own
  // checkpoint has neither); load() after the simulation's load(), into a plate made on the same
  // wall.
  void save(ByteWriter& w, const Simulation& sim) const;
  void load(ByteReader& r, Simulation& sim);

 private:
  void find_glued(const Simulation& sim) const;  // indices of ids_ after a reorder
  std::size_t wall_;
  Vec3 normal_;
  std::vector<std::uint64_t> ids_;
  mutable std::vector<std::size_t> index_;
  PlateControl control_;
  Vec3 velocity_, displacement_;
  Vec3 moved_since_build_;
  double integral_ = 0.0;  // N s, of the load error
  long builds_seen_ = -1;
};

}  // namespace silodem
