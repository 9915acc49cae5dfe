// The 3MF file, through lib3mf 1.8's C interface (Debian's lib3mf-dev).
#include "multidir/assembly/three_mf.h"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <memory>

#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::assembly {

namespace {

using namespace NMR;

// Releases a lib3mf handle when it goes out of scope.
struct Handle {
  PLib3MFBase* pointer = nullptr;
  Handle() = default;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (pointer) lib3mf_release(pointer);
  }
  PLib3MFBase** out() { return &pointer; }
};

bool ok(LIB3MFRESULT result) { return result == LIB3MF_OK; }

// The plate's shift and the item's placement, as the build item's 3 x 4 matrix; the mesh is the item in its
// laid frame (the placement undone).
Eigen::Isometry3d placement(const PlateItem& item, const PlateOptions& options) {
  const double shift = item.plate * (options.bedMax.x() - options.bedMin.x() + kPlateGapMm);
  // The item's mesh is already placed on its plate; its own frame has its box corner at the origin.
  Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY);
  for (const core::Vec3& v : item.mesh.vertices) low = low.cwiseMin(v);
  return Eigen::Isometry3d(Eigen::Translation3d(low + Eigen::Vector3d(shift, 0, 0)));
}

}  // namespace

std::vector<ThreeMfItem> threeMfItems(const PlateLayout& layout, const PlateOptions& options) {
  std::vector<ThreeMfItem> items;
  for (const PlateItem& item : layout.items) {
    ThreeMfItem out;
    out.name = item.name;
    out.vertices = item.mesh.vertices.size();
    out.triangles = item.mesh.triangles.size();
    out.volumeMm3 = core::signedVolume(item.mesh);
    out.transform = placement(item, options).matrix().topRows<3>();
    items.push_back(out);
  }
  return items;
}

core::Status write3mf(const PlateLayout& layout, const PlateOptions& options, const std::string& path) {
  const auto failed = [&](const std::string& what) {
    return core::Error{core::ErrorCode::WriteFailed, "lib3mf could not " + what + ": check the folder", path};
  };
  Handle model;
  if (!ok(lib3mf_createmodel(model.out()))) return failed("create a model");
  for (const PlateItem& item : layout.items) {
    const Eigen::Isometry3d place = placement(item, options);
    const Eigen::Isometry3d back = place.inverse();
    std::vector<MODELMESHVERTEX> vertices(item.mesh.vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const core::Vec3 local = back * item.mesh.vertices[i];
      for (int k = 0; k < 3; ++k) vertices[i].m_fPosition[k] = static_cast<FLOAT>(local[k]);
    }
    std::vector<MODELMESHTRIANGLE> triangles(item.mesh.triangles.size());
    for (std::size_t f = 0; f < triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) triangles[f].m_nIndices[k] = static_cast<DWORD>(item.mesh.triangles[f][static_cast<std::size_t>(k)]);
    Handle object;
    if (!ok(lib3mf_model_addmeshobject(model.pointer, object.out()))) return failed("add " + item.name);
    if (!ok(lib3mf_meshobject_setgeometry(object.pointer, vertices.data(), static_cast<DWORD>(vertices.size()),
                                          triangles.data(), static_cast<DWORD>(triangles.size()))) ||
        !ok(lib3mf_object_setnameutf8(object.pointer, item.name.c_str())))
      return failed("store " + item.name);
    MODELTRANSFORM transform;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) transform.m_fFields[r][c] = static_cast<FLOAT>(place.matrix()(r, c));
    Handle buildItem;
    if (!ok(lib3mf_model_addbuilditem(model.pointer, object.pointer, &transform, buildItem.out())))
      return failed("place " + item.name);
  }
  Handle writer;
  if (!ok(lib3mf_model_querywriter(model.pointer, "3mf", writer.out()))) return failed("make a 3MF writer");
  if (!ok(lib3mf_writer_writetofileutf8(writer.pointer, path.c_str()))) return failed("write the file");
  return core::Done{};
}

core::Result<std::vector<ThreeMfItem>> read3mf(const std::string& path) {
  const auto malformed = [&](const std::string& what) {
    return core::Error{core::ErrorCode::MalformedFile, "lib3mf could not " + what, path};
  };
  Handle model, reader, iterator;
  if (!ok(lib3mf_createmodel(model.out()))) return malformed("create a model");
  if (!ok(lib3mf_model_queryreader(model.pointer, "3mf", reader.out()))) return malformed("make a 3MF reader");
  if (!ok(lib3mf_reader_readfromfileutf8(reader.pointer, path.c_str()))) return malformed("read the file");
  if (!ok(lib3mf_model_getbuilditems(model.pointer, iterator.out()))) return malformed("list the build items");
  std::vector<ThreeMfItem> items;
  BOOL more = false;
  while (ok(lib3mf_builditemiterator_movenext(iterator.pointer, &more)) && more) {
    Handle buildItem;
    if (!ok(lib3mf_builditemiterator_getcurrent(iterator.pointer, buildItem.out()))) return malformed("read an item");
    PLib3MFModelObjectResource* object = nullptr;  // owned by the model
    Handle objectHandle;
    if (!ok(lib3mf_builditem_getobjectresource(buildItem.pointer, objectHandle.out())))
      return malformed("read an item's object");
    object = objectHandle.pointer;
    ThreeMfItem item;
    ULONG needed = 0;
    lib3mf_object_getnameutf8(object, nullptr, 0, &needed);
    std::string name(needed + 1, '\0');
    lib3mf_object_getnameutf8(object, name.data(), static_cast<ULONG>(name.size()), &needed);
    item.name = name.c_str();
    DWORD vertexCount = 0, triangleCount = 0;
    if (!ok(lib3mf_meshobject_getvertexcount(object, &vertexCount)) ||
        !ok(lib3mf_meshobject_gettrianglecount(object, &triangleCount)))
      return malformed("count " + item.name + "'s mesh");
    std::vector<MODELMESHVERTEX> vertices(vertexCount);
    std::vector<MODELMESHTRIANGLE> triangles(triangleCount);
    if (!ok(lib3mf_meshobject_getvertices(object, vertices.data(), vertexCount, nullptr)) ||
        !ok(lib3mf_meshobject_gettriangleindices(object, triangles.data(), triangleCount, nullptr)))
      return malformed("read " + item.name + "'s mesh");
    core::TriangleMesh mesh;
    for (const MODELMESHVERTEX& v : vertices) mesh.vertices.emplace_back(v.m_fPosition[0], v.m_fPosition[1], v.m_fPosition[2]);
    for (const MODELMESHTRIANGLE& t : triangles)
      mesh.triangles.push_back({static_cast<std::int32_t>(t.m_nIndices[0]), static_cast<std::int32_t>(t.m_nIndices[1]),
                                static_cast<std::int32_t>(t.m_nIndices[2])});
    mesh.resetOrigins();
    item.vertices = vertexCount;
    item.triangles = triangleCount;
    item.volumeMm3 = core::signedVolume(mesh);
    MODELTRANSFORM transform;
    if (!ok(lib3mf_builditem_getobjecttransform(buildItem.pointer, &transform)))
      return malformed("read " + item.name + "'s transform");
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) item.transform(r, c) = transform.m_fFields[r][c];
    items.push_back(std::move(item));
  }
  return items;
}

}  // namespace multidir::assembly
