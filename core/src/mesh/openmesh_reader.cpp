// Reads OFF, OBJ and PLY through OpenMesh's readers into a raw polygon soup. The importer below keeps
// every polygon as the file gives it: loading into an OpenMesh PolyMesh would drop non-manifold faces
// without a word and hide the very defects the checks must report.
#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include "mesh/mesh_formats.h"

namespace multidir::core::detail {
namespace {

using OpenMesh::EdgeHandle;
using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

class SoupImporter : public OpenMesh::IO::BaseImporter {
 public:
  RawSoup soup;
  std::size_t calls = 0;     // add_face calls, for messages
  std::size_t polygons = 0;  // polygons kept (three or more corners, indices in range)
  std::int64_t badIndex = -1;  // the first out-of-range index a reader passed on, if any
  std::size_t badIndexPolygon = 0;

  VertexHandle add_vertex(const OpenMesh::Vec3f& p) override { return addPoint(p[0], p[1], p[2]); }
  VertexHandle add_vertex(const OpenMesh::Vec3d& p) override { return addPoint(p[0], p[1], p[2]); }
  VertexHandle add_vertex() override { return addPoint(0.0, 0.0, 0.0); }
  void set_point(VertexHandle v, const OpenMesh::Vec3f& p) override {
    if (v.is_valid() && static_cast<std::size_t>(v.idx()) < soup.vertices.size())
      soup.vertices[static_cast<std::size_t>(v.idx())] = Vec3(p[0], p[1], p[2]);
  }

  FaceHandle add_face(const VHandles& corners) override {
    const std::size_t polygon = calls++;
    for (const VertexHandle& v : corners) {
      if (!v.is_valid() || static_cast<std::size_t>(v.idx()) >= soup.vertices.size()) {
        if (badIndex < 0) {
          badIndex = v.idx();
          badIndexPolygon = polygon;
        }
        return FaceHandle();
      }
    }
    if (corners.size() < 3) return FaceHandle();  // counted by the structure check
    ++polygons;
    // Fan triangulation: exact for the convex polygons exporters write.
    for (std::size_t k = 1; k + 1 < corners.size(); ++k)
      soup.triangles.push_back({corners[0].idx(), corners[k].idx(), corners[k + 1].idx()});
    return FaceHandle(static_cast<int>(polygon));
  }

  // Everything below is data MultiDir does not use (normals, colours, texture, halfedge structure).
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_normal(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

  // Reservation is skipped on purpose: the counts come from the file and were checked, but a reader may
  // call this before its own checks.
  void reserve(unsigned int, unsigned int, unsigned int) override {}
  size_t n_vertices() const override { return soup.vertices.size(); }
  size_t n_faces() const override { return calls; }
  size_t n_edges() const override { return 0; }

 private:
  VertexHandle addPoint(double x, double y, double z) {
    soup.vertices.emplace_back(x, y, z);
    return VertexHandle(static_cast<int>(soup.vertices.size() - 1));
  }
};

// OpenMesh writes warnings (missing .mtl files, unknown properties) to omerr/omlog; a library must not
// print, so they are off during a read and restored afterwards.
class QuietOpenMesh {
 public:
  QuietOpenMesh()
      : m_err(::omerr().is_enabled()), m_log(::omlog().is_enabled()),
        m_out(::omout().is_enabled()) {
    ::omerr().disable();
    ::omlog().disable();
    ::omout().disable();
  }
  ~QuietOpenMesh() {
    if (m_err) ::omerr().enable();
    if (m_log) ::omlog().enable();
    if (m_out) ::omout().enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

 private:
  bool m_err, m_log, m_out;
};

template <typename ReadFn>
Result<RawSoup> readInto(ReadFn&& read, const std::string& name, const FileShape& shape) {
  SoupImporter importer;
  importer.soup.vertices.reserve(shape.vertices);
  importer.soup.triangles.reserve(shape.triangles);
  bool ok = false;
  {
    QuietOpenMesh quiet;
    OpenMesh::IO::Options options;
    ok = read(importer, options);
  }
  if (!ok)
    return malformed(name, "OpenMesh could not read the file although its structure looked right; "
                           "export it again or convert it to another format");
  if (importer.badIndex >= 0 || importer.badIndex < -1)
    return malformed(name, "polygon " + std::to_string(importer.badIndexPolygon) + " refers to vertex " +
                               std::to_string(importer.badIndex) + ", but there are only " +
                               std::to_string(importer.soup.vertices.size()) + " vertices");
  if (importer.soup.vertices.size() != shape.vertices)
    return malformed(name, "the file holds " + withThousands(shape.vertices) + " vertices but " +
                               withThousands(importer.soup.vertices.size()) + " were read");
  const std::size_t expected = shape.polygons - shape.shortPolygons;
  if (importer.polygons > expected)
    return malformed(name, "the file holds " + withThousands(expected) + " polygons but " +
                               withThousands(importer.polygons) + " were read");
  // Some OpenMesh readers skip polygons with a repeated corner; those, like polygons with fewer than three
  // corners, are degenerate.
  importer.soup.droppedByReader += (expected - importer.polygons) + shape.shortPolygons;
  return std::move(importer.soup);
}

}  // namespace

Result<RawSoup> readWithOpenMesh(std::istream& in, const std::string& extension, const std::string& name,
                                 const FileShape& shape) {
  return readInto([&](SoupImporter& importer, OpenMesh::IO::Options& options) {
    return OpenMesh::IO::IOManager().read(in, extension, importer, options);
  }, name, shape);
}

}  // namespace multidir::core::detail
