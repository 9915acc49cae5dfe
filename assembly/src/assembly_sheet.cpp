// The assembly sheet: gluing order, pictures and tables as one HTML page (docs/apart.md, "Assembly sheet").
#include "multidir/assembly/assembly_sheet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "multidir/assembly/picture.h"
#include "multidir/core/mesh/mesh_measure.h"

namespace multidir::assembly {

using core::TriangleMesh;

namespace {

const Colour kGlued(0.78, 0.78, 0.78);     // parts glued in earlier steps
const Colour kArriving(0.95, 0.55, 0.15);  // the part this step adds
const Colour kPartner(0.25, 0.5, 0.9);     // the parts it is glued to
const Colour kDowel(0.85, 0.1, 0.1);

Colour paletteColour(std::size_t k) {
  static const Colour palette[] = {{0.95, 0.55, 0.15}, {0.25, 0.5, 0.9}, {0.3, 0.7, 0.35}, {0.8, 0.35, 0.6},
                                   {0.55, 0.45, 0.85}, {0.9, 0.8, 0.2},  {0.3, 0.75, 0.75}, {0.7, 0.5, 0.3}};
  return palette[k % (sizeof palette / sizeof palette[0])];
}

Vec3 centroidOf(const TriangleMesh& mesh) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& v : mesh.vertices) sum += v;
  return mesh.vertices.empty() ? sum : Vec3(sum / static_cast<double>(mesh.vertices.size()));
}

std::string number(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string duration(double seconds) {
  const long long s = std::llround(seconds);
  char text[64];
  std::snprintf(text, sizeof text, "%lldh %02lldm %02llds", s / 3600, (s / 60) % 60, s % 60);
  return text;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string twoDigits(int k) {
  char text[16];
  std::snprintf(text, sizeof text, "%02d", k);
  return text;
}

// A view looking at `target` from the side `from` points to, tilted so no face is seen exactly edge-on.
View viewFrom(const Vec3& from, const Vec3& upHint) {
  View view;
  view.looking = -from.normalized();
  Vec3 up = upHint - upHint.dot(view.looking) * view.looking;
  if (up.norm() < 1e-6) up = view.looking.unitOrthogonal();
  view.up = up.normalized();
  return view;
}

}  // namespace

std::vector<GluingStep> gluingOrder(const core::ApartPlan& plan) {
  std::vector<GluingStep> steps;
  const std::size_t n = plan.parts.size();
  if (n == 0) return steps;
  std::vector<char> glued(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    int pick = -1;
    double bestArea = -1.0;
    for (std::size_t p = 0; p < n && k > 0; ++p) {
      if (glued[p]) continue;
      double area = 0.0;
      for (const core::ApartJoint& j : plan.joints)
        if ((j.upper == static_cast<int>(p) && glued[static_cast<std::size_t>(j.lower)]) ||
            (j.lower == static_cast<int>(p) && glued[static_cast<std::size_t>(j.upper)]))
          area += j.areaMm2;
      if (area > bestArea) {
        bestArea = area;
        pick = static_cast<int>(p);
      }
    }
    if (k == 0) pick = 0;
    GluingStep step;
    step.part = pick;
    for (std::size_t j = 0; j < plan.joints.size(); ++j) {
      const core::ApartJoint& joint = plan.joints[j];
      if ((joint.upper == pick && glued[static_cast<std::size_t>(joint.lower)]) ||
          (joint.lower == pick && glued[static_cast<std::size_t>(joint.upper)]))
        step.joints.push_back(static_cast<int>(j));
    }
    glued[static_cast<std::size_t>(pick)] = 1;
    steps.push_back(std::move(step));
  }
  return steps;
}

core::Result<Sheet> assemblySheet(const SheetInput& in) {
  if (!in.plan || !in.layout || !in.labels || !in.parts || !in.dowels || !in.plates)
    return core::Error{core::ErrorCode::InvalidParameter, "the sheet needs the plan, dowels, labels, parts and plates",
                       "assembly sheet"};
  const core::ApartPlan& plan = *in.plan;
  if (in.parts->size() != plan.parts.size() || in.labels->size() != plan.parts.size() ||
      in.dowels->size() != in.layout->dowels.size())
    return core::Error{core::ErrorCode::InvalidParameter,
                       "the parts, labels and dowels given do not match the plan's parts and dowels", "assembly sheet"};
  Sheet sheet;
  const Vec3 up = plan.parts.front().printingDirection;
  const Vec3 side = up.unitOrthogonal();
  const Vec3 front = up.cross(side);
  TriangleMesh all;
  for (const TriangleMesh& part : *in.parts) {
    const auto base = static_cast<std::int32_t>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const core::Triangle& t : part.triangles) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  const core::BoundingBox box = core::boundingBox(all);
  const Vec3 middle = 0.5 * (box.min + box.max);
  const double size = (box.max - box.min).norm();
  auto addPicture = [&](const std::string& name, const Image& image) {
    sheet.pictures.push_back({"sheet/" + name, encodePng(image)});
    return "sheet/" + name;
  };

  std::string html =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + escaped(in.title) +
      "</title>\n<style>body{font-family:sans-serif;max-width:60em;margin:1em auto}table{border-collapse:collapse}"
      "td,th{border:1px solid #bbb;padding:2px 8px;text-align:right}th{background:#eee}"
      "td:first-child,th:first-child{text-align:left}img{border:1px solid #ccc}.step{margin:1.5em 0}</style>"
      "</head><body>\n<h1>" + escaped(in.title) + "</h1>\n";

  // The parts, exploded from the model's middle, each with its number.
  {
    std::vector<ColouredMesh> meshes;
    std::vector<Caption> captions;
    for (std::size_t p = 0; p < in.parts->size(); ++p) {
      const Vec3 c = centroidOf((*in.parts)[p]);
      const Vec3 shift = 0.35 * (c - middle);
      meshes.push_back({&(*in.parts)[p], paletteColour(p), shift});
      captions.push_back({std::to_string(p + 1), c + shift});
    }
    View view = viewFrom(front + 0.6 * side + 0.5 * up, up);
    view.width = 640;
    view.height = 480;
    html += "<h2>The parts</h2>\n<p><img src=\"" + addPicture("parts.png", render(meshes, captions, view)) +
            "\" alt=\"the parts, exploded, with their numbers\"></p>\n";
  }
  html += "<table><tr><th>part</th><th>file</th><th>volume cm<sup>3</sup></th><th>number on the part</th></tr>\n";
  for (std::size_t p = 0; p < plan.parts.size(); ++p) {
    const PartLabel& label = (*in.labels)[p];
    const std::string mark = label.placed ? "sunk " + number(label.heightMm, 0) + " mm tall into joint " +
                                                std::to_string(label.joint + 1) + "'s face"
                                          : "none: " + label.note;
    html += "<tr><td>" + std::to_string(p + 1) + "</td><td>part-" + twoDigits(static_cast<int>(p + 1)) +
            ".stl</td><td>" + number(core::signedVolume((*in.parts)[p]) / 1000.0, 2) + "</td><td>" +
            escaped(mark) + "</td></tr>\n";
  }
  html += "</table>\n";

  // Gluing, one step a picture: the parts glued so far grey, the part that comes orange and moved off along
  // its joints, the parts it meets blue, its dowels red in the holes of the glued side.
  html += "<h2>Gluing order</h2>\n<p>Put glue on both faces of each joint and in its holes, push the dowels into "
          "the holes of the parts already glued, then press the next part on. Each dowel fits one hole size "
          "only, so the parts go together one way.</p>\n";
  const std::vector<GluingStep> steps = gluingOrder(plan);
  std::vector<char> glued(plan.parts.size(), 0);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const GluingStep& step = steps[k];
    const auto arriving = static_cast<std::size_t>(step.part);
    if (k > 0) {
      Vec3 away = Vec3::Zero();
      std::vector<char> partner(plan.parts.size(), 0);
      for (int j : step.joints) {
        const core::ApartJoint& joint = plan.joints[static_cast<std::size_t>(j)];
        away += (joint.upper == step.part ? 1.0 : -1.0) * joint.plane.normal;
        partner[static_cast<std::size_t>(joint.upper == step.part ? joint.lower : joint.upper)] = 1;
      }
      if (away.norm() < 1e-9) away = up;
      away.normalize();
      std::vector<ColouredMesh> meshes;
      std::vector<Caption> captions;
      for (std::size_t p = 0; p < plan.parts.size(); ++p)
        if (glued[p]) {
          meshes.push_back({&(*in.parts)[p], partner[p] ? kPartner : kGlued, Vec3::Zero()});
          if (partner[p]) captions.push_back({std::to_string(p + 1), centroidOf((*in.parts)[p])});
        }
      const Vec3 shift = 0.3 * size * away;
      meshes.push_back({&(*in.parts)[arriving], kArriving, shift});
      captions.push_back({std::to_string(arriving + 1), centroidOf((*in.parts)[arriving]) + shift});
      std::string joints;
      for (std::size_t d = 0; d < in.layout->dowels.size(); ++d) {
        const Dowel& dowel = in.layout->dowels[d];
        if (std::find(step.joints.begin(), step.joints.end(), dowel.joint) == step.joints.end()) continue;
        meshes.push_back({&(*in.dowels)[d], kDowel, Vec3::Zero()});
      }
      const Vec3 across = away.unitOrthogonal();
      View view = viewFrom(across + 0.7 * away + 0.3 * up.cross(away).normalized(), up);
      html += "<div class=\"step\"><h3>Step " + std::to_string(k) + ": part " + std::to_string(arriving + 1) +
              "</h3>\n<p><img src=\"" +
              addPicture("step-" + twoDigits(static_cast<int>(k)) + ".png", render(meshes, captions, view)) +
              "\" alt=\"step " + std::to_string(k) + "\"></p>\n<ul>\n";
      for (int j : step.joints) {
        const core::ApartJoint& joint = plan.joints[static_cast<std::size_t>(j)];
        const int other = joint.upper == step.part ? joint.lower : joint.upper;
        std::string dowels;
        int count = 0;
        for (const Dowel& dowel : in.layout->dowels)
          if (dowel.joint == j) {
            dowels += (count++ ? ", " : "") + number(dowel.diameterMm, 1) + " x " + number(dowel.lengthMm, 1) + " mm";
          }
        const std::string note = in.layout->joints[static_cast<std::size_t>(j)].note;
        joints += "<li>joint " + std::to_string(j + 1) + " with part " + std::to_string(other + 1) + " (" +
                  number(joint.areaMm2, 0) + " mm<sup>2</sup>): " +
                  (count ? std::to_string(count) + (count == 1 ? " dowel " : " dowels ") + dowels : "no dowel") +
                  (note.empty() ? "" : "; " + escaped(note)) + "</li>\n";
      }
      html += joints + "</ul></div>\n";
    } else {
      html += "<p>Start with part " + std::to_string(arriving + 1) + ".</p>\n";
    }
    glued[arriving] = 1;
  }

  // The plates as printed, seen from above, with the parts' numbers; the slicer's estimates.
  html += "<h2>Plates</h2>\n";
  for (int plate = 0; plate < in.plates->plates; ++plate) {
    const TriangleMesh mesh = plateMesh(*in.plates, plate);
    std::vector<Caption> captions;
    std::string items;
    for (const PlateItem& item : in.plates->items) {
      if (item.plate != plate) continue;
      items += (items.empty() ? "" : ", ") + item.name;
      if (item.name.rfind("part-", 0) == 0)
        captions.push_back({std::to_string(std::stoi(item.name.substr(5))), centroidOf(item.mesh)});
    }
    const View view = viewFrom(Vec3(0, -0.35, 1), Vec3::UnitY());
    html += "<h3>Plate " + std::to_string(plate + 1) + "</h3>\n<p><img src=\"" +
            addPicture("plate-" + std::to_string(plate + 1) + ".png",
                       render({{&mesh, Colour(0.6, 0.65, 0.75), Vec3::Zero()}}, captions, view)) +
            "\" alt=\"plate " + std::to_string(plate + 1) + "\"></p>\n<p>" + escaped(items) + "</p>\n";
  }
  if (in.estimates.empty()) {
    html += "<p>Not sliced: no estimates.</p>\n";
  } else {
    html += "<table><tr><th></th><th>time</th><th>filament cm<sup>3</sup></th><th>of which support cm<sup>3</sup>"
            "</th></tr>\n";
    for (const SheetEstimate& e : in.estimates)
      html += "<tr><td>" + escaped(e.what) + "</td><td>" + duration(e.seconds) + "</td><td>" +
              number(e.filamentCm3, 2) + "</td><td>" + number(e.supportCm3, 2) + "</td></tr>\n";
    html += "</table>\n<p>The slicer's estimates (PrusaSlicer, the printer's profile).</p>\n";
  }
  html += "</body></html>\n";
  sheet.html = std::move(html);
  return sheet;
}

}  // namespace multidir::assembly
