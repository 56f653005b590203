// SPDX-License-Identifier: MIT
// ParaView output: VTK XML PolyData (.vtp) with binary appended data (raw, little endian, UInt64
// block headers), a .pvd time collection, and the silo walls as a surface. Every file is written
// as "<name>.partial" and renamed when complete.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/simulation.hpp"
#include "scenario/silo_geometry.hpp"

namespace silodem {

class VtpWriter {
 public:
  explicit VtpWriter(std::vector<Vec3> points) : points_(std::move(points)) {}
  void add(std::string name, std::vector<double> values, int components = 1);
  void add(std::string name, std::vector<std::int32_t> values);
  void add(std::string name, std::vector<std::int64_t> values);
  // One vertex cell per point (particles), or polygons (surfaces) given by point indices.
  void vertices() { verts_ = true; }
  void polygons(std::vector<std::int64_t> connectivity, std::vector<std::int64_t> offsets);
  void write(const std::string& path) const;

 private:
  struct Array {
    std::string name, type;
    int components = 1;
    std::vector<unsigned char> bytes;
  };
  std::vector<Vec3> points_;
  std::vector<Array> arrays_;
  bool verts_ = false;
  std::vector<std::int64_t> conn_, offs_;
};

// Particles with radius, coal, id, velocity, speed, cohesive force (sum over the contacts) and
// contact count (particles + walls, touching).
void write_particles_vtp(const std::string& path, const Simulation& sim, const ContactTally& t);

// The cone and cylinder walls as a quad surface (`segments` around the axis).
void write_silo_vtp(const std::string& path, const SiloGeometry& g, int segments = 96);

// A .pvd collection, rewritten (atomically) after each frame so that it is always valid.
class PvdCollection {
 public:
  explicit PvdCollection(std::string path) : path_(std::move(path)) {}
  void add(double time, const std::string& file);  // file relative to the .pvd
  // A frame written before a checkpoint (resume): listed again without rewriting the file.
  void restore(double time, const std::string& file) { items_.emplace_back(time, file); }
  std::vector<double> times() const {
    std::vector<double> t;
    for (const auto& it : items_) t.push_back(it.first);
    return t;
  }
  void write() const;
  std::size_t frames() const { return items_.size(); }

 private:
  std::string path_;
  std::vector<std::pair<double, std::string>> items_;
};

}  // namespace silodem
