// SPDX-License-Identifier: MIT
#include "io/vtk.hpp"

#include "io/atomic_file.hpp"

#include <fmt/format.h>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace silodem {
namespace {

static_assert(std::endian::native == std::endian::little, "the VTK writer assumes little endian");

template <class T>
std::vector<unsigned char> bytes_of(const std::vector<T>& v) {
  std::vector<unsigned char> b(v.size() * sizeof(T));
  if (!v.empty()) std::memcpy(b.data(), v.data(), b.size());
  return b;
}

}  // namespace

void VtpWriter::add(std::string name, std::vector<double> values, int components) {
  if (values.size() != points_.size() * std::size_t(components))
    throw std::logic_error("VtpWriter: array " + name + " has the wrong length");
  arrays_.push_back({std::move(name), "Float64", components, bytes_of(values)});
}

void VtpWriter::add(std::string name, std::vector<std::int32_t> values) {
  if (values.size() != points_.size())
    throw std::logic_error("VtpWriter: array " + name + " has the wrong length");
  arrays_.push_back({std::move(name), "Int32", 1, bytes_of(values)});
}

void VtpWriter::add(std::string name, std::vector<std::int64_t> values) {
  if (values.size() != points_.size())
    throw std::logic_error("VtpWriter: array " + name + " has the wrong length");
  arrays_.push_back({std::move(name), "Int64", 1, bytes_of(values)});
}

void VtpWriter::polygons(std::vector<std::int64_t> connectivity,
                         std::vector<std::int64_t> offsets) {
  conn_ = std::move(connectivity);
  offs_ = std::move(offsets);
}

void VtpWriter::write(const std::string& path) const {
  const std::size_t n = points_.size();
  std::vector<double> xyz;
  xyz.reserve(3 * n);
  for (const auto& p : points_) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  std::vector<std::int64_t> conn = conn_, offs = offs_;
  if (verts_) {
    conn.resize(n);
    offs.resize(n);
    for (std::size_t i = 0; i < n; ++i) conn[i] = std::int64_t(i), offs[i] = std::int64_t(i + 1);
  }
  // Appended blocks in the order they are declared in the XML.
  std::vector<const std::vector<unsigned char>*> blocks;
  for (const auto& a : arrays_) blocks.push_back(&a.bytes);
  const auto b_xyz = bytes_of(xyz), b_conn = bytes_of(conn), b_offs = bytes_of(offs);
  blocks.push_back(&b_xyz);
  blocks.push_back(&b_conn);
  blocks.push_back(&b_offs);
  std::vector<std::uint64_t> offset(blocks.size());
  std::uint64_t at = 0;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    offset[k] = at;
    at += sizeof(std::uint64_t) + blocks[k]->size();
  }
  const std::size_t cells = verts_ ? n : offs.size();
  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <PolyData>\n"
      "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"0\" "
      "NumberOfStrips=\"0\" NumberOfPolys=\"{}\">\n"
      "      <PointData>\n",
      n, verts_ ? cells : 0, verts_ ? 0 : cells);
  for (std::size_t k = 0; k < arrays_.size(); ++k)
    xml += fmt::format(
        "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
        "format=\"appended\" offset=\"{}\"/>\n",
        arrays_[k].type, arrays_[k].name, arrays_[k].components, offset[k]);
  const std::size_t a = arrays_.size();
  xml += fmt::format(
      "      </PointData>\n"
      "      <Points>\n"
      "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
      "format=\"appended\" offset=\"{}\"/>\n"
      "      </Points>\n"
      "      <{}>\n"
      "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" "
      "offset=\"{}\"/>\n"
      "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"{}\"/>\n"
      "      </{}>\n"
      "    </Piece>\n"
      "  </PolyData>\n"
      "  <AppendedData encoding=\"raw\">\n   _",
      offset[a], verts_ ? "Verts" : "Polys", offset[a + 1], offset[a + 2],
      verts_ ? "Verts" : "Polys");
  std::vector<std::uint64_t> lengths;
  for (const auto* b : blocks) lengths.push_back(b->size());
  static const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
  std::vector<std::string_view> parts = {xml};
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    parts.emplace_back(reinterpret_cast<const char*>(&lengths[k]), sizeof(std::uint64_t));
    parts.emplace_back(reinterpret_cast<const char*>(blocks[k]->data()), blocks[k]->size());
  }
  parts.emplace_back(tail);
  write_atomically(path, parts, false);
}

void write_particles_vtp(const std::string& path, const Simulation& sim, const ContactTally& t) {
  const ParticleStore& p = sim.particles();
  const std::size_t n = p.size();
  std::vector<Vec3> x(p.x.begin(), p.x.begin() + std::ptrdiff_t(n));
  std::vector<double> radius(n), vel(3 * n), speed(n), coh(n);
  std::vector<std::int32_t> coal(n), contacts(n);
  std::vector<std::int64_t> id(n);
  for (std::size_t i = 0; i < n; ++i) {
    radius[i] = p.radius[i];
    vel[3 * i] = p.v[i].x, vel[3 * i + 1] = p.v[i].y, vel[3 * i + 2] = p.v[i].z;
    speed[i] = norm(p.v[i]);
    coh[i] = t.cohesion_sum[i];
    coal[i] = std::int32_t(p.material[i]);
    contacts[i] = std::int32_t(t.particle_contacts[i] + t.wall_contacts[i]);
    id[i] = std::int64_t(p.id[i]);
  }
  VtpWriter w(std::move(x));
  w.add("radius", std::move(radius));
  w.add("coal", std::move(coal));
  w.add("id", std::move(id));
  w.add("velocity", std::move(vel), 3);
  w.add("speed", std::move(speed));
  w.add("cohesive_force", std::move(coh));
  w.add("contacts", std::move(contacts));
  w.vertices();
  w.write(path);
}

void write_silo_vtp(const std::string& path, const SiloGeometry& g, int segments) {
  // Rings at the outlet, the cone/cylinder junction and the top; quads between them.
  const double z[3] = {0.0, g.cone_height, g.total_height()};
  const double r[3] = {g.outlet_radius(), g.top_radius(), g.top_radius()};
  const int rings = g.cylinder_height > 0 ? 3 : 2;
  std::vector<Vec3> pts;
  for (int k = 0; k < rings; ++k)
    for (int s = 0; s < segments; ++s) {
      const double a = 2.0 * std::numbers::pi * s / segments;
      pts.push_back({r[k] * std::cos(a), r[k] * std::sin(a), z[k]});
    }
  std::vector<std::int64_t> conn, offs;
  for (int k = 0; k + 1 < rings; ++k)
    for (int s = 0; s < segments; ++s) {
      const int s1 = (s + 1) % segments;
      for (int q :
           {k * segments + s, k * segments + s1, (k + 1) * segments + s1, (k + 1) * segments + s})
        conn.push_back(q);
      offs.push_back(std::int64_t(conn.size()));
    }
  VtpWriter w(std::move(pts));
  w.polygons(std::move(conn), std::move(offs));
  w.write(path);
}

void PvdCollection::add(double time, const std::string& file) {
  items_.emplace_back(time, file);
  write();
}

void PvdCollection::write() const {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& [t, f] : items_)
    xml +=
        fmt::format("    <DataSet timestep=\"{:.9g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t, f);
  xml += "  </Collection>\n</VTKFile>\n";
  write_atomically(path_, {xml}, false);
}

}  // namespace silodem
