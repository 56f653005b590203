// SPDX-License-Identifier: MIT
// Writes a known state as ParaView files for vtk_readback.py: three particles (two of them a
// bonded cohesive pair, the third apart), two frames in a .pvd, and the paper's silo surface.
// Usage: write_vtk_sample DIR
#include <cstdio>
#include <filesystem>

#include "../../physics/helpers.hpp"
#include "io/vtk.hpp"

int main(int argc, char** argv) {
  using namespace silodem;
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_vtk_sample DIR\n");
    return 2;
  }
  const std::filesystem::path dir(argv[1]);
  std::filesystem::create_directories(dir);
  test::Laws l;
  l.cohesion = "overlap-only";
  SimulationSettings s;
  s.dt = 1e-6;
  s.gravity = {};
  s.threads = 1;
  Simulation sim(test::model_of(l, {0.05}), s);
  const double r = 0.004;
  sim.particles().add({0.0, 0.0, 0.1}, {0.0, 0.0, -0.3}, {}, r, 4e-4, 0);
  sim.particles().add({2 * r * 0.999, 0.0, 0.1}, {0.3, 0.4, 0.0}, {}, r, 4e-4, 0);
  sim.particles().add({0.05, 0.05, 0.2}, {}, {}, 1.5 * r, 9e-4, 0);
  sim.initialize();
  PvdCollection pvd((dir / "particles.pvd").string());
  write_particles_vtp((dir / "particles_000000.vtp").string(), sim, sim.contact_tally());
  pvd.add(0.0, "particles_000000.vtp");
  sim.particles().remove(2);  // the second frame has two particles
  write_particles_vtp((dir / "particles_000001.vtp").string(), sim, sim.contact_tally());
  pvd.add(0.5, "particles_000001.vtp");
  write_silo_vtp((dir / "silo.vtp").string(), SiloGeometry{}, 48);
  return 0;
}
