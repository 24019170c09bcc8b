#include "preprocess/asset_report.hpp"

#include "gfield/asset_source.hpp"
#include "gfield/file_read.hpp"

namespace gfield {
namespace {

nlohmann::json box_to_json(const Box& box) {
  return {{"min", {box.min.x, box.min.y, box.min.z}}, {"max", {box.max.x, box.max.y, box.max.z}}};
}

Box box_from_json(const nlohmann::json& j) {
  const auto vec = [](const nlohmann::json& v) {
    return glm::vec3(v.at(0).get<float>(), v.at(1).get<float>(), v.at(2).get<float>());
  };
  return {vec(j.at("min")), vec(j.at("max"))};
}

nlohmann::json stage_seconds_to_json(const AssetStageSeconds& s) {
  return {{"mesh", s.mesh},
          {"image", s.image},
          {"image_write", s.image_write},
          {"field", s.field},
          {"field_write", s.field_write},
          {"verify", s.verify}};
}

AssetStageSeconds stage_seconds_from_json(const nlohmann::json& j) {
  return {j.at("mesh").get<double>(),        j.at("image").get<double>(),
          j.at("image_write").get<double>(), j.at("field").get<double>(),
          j.at("field_write").get<double>(), j.at("verify").get<double>()};
}

}  // namespace

nlohmann::json asset_report_to_json(const AssetReport& r) {
  nlohmann::json j = {{"mesh", r.mesh},
                      {"source_path", r.source_path},
                      {"build_id", r.build_id},
                      {"inputs", r.inputs},
                      {"warnings", r.warnings},
                      {"topology", topology_to_json(r.topology)},
                      {"geometry_image", geometry_image_report_to_json(r.geometry_image)},
                      {"box", box_to_json(r.box)},
                      {"geometry_field", field_file_report_to_json(r.geometry_field)},
                      {"files",
                       {{"geometry_image", r.files.image},
                        {"parameterized_mesh", r.files.parameterized_mesh},
                        {"geometry_field", r.files.field},
                        {"geometry_image_bytes", r.image_file_bytes},
                        {"geometry_field_bytes", r.geometry_field.file_bytes}}},
                      {"stage_seconds", stage_seconds_to_json(r.stage_seconds)},
                      {"seconds", r.seconds}};
  if (!r.mesh_part.empty())
    j["mesh_part"] = r.mesh_part;
  if (r.mesh_modified_ns != 0)
    j["mesh_modified_ns"] = r.mesh_modified_ns;
  j["geometry_image"]["size"] = r.image_size;
  j["geometry_image"]["write_seconds"] = r.image_write_seconds;
  j["geometry_field"]["precision"] = r.field_precision == ExrPrecision::kHalf ? "half" : "float";
  if (r.accuracy)
    j["accuracy"] = verify_report_to_json(*r.accuracy);
  return j;
}

AssetReport asset_report_from_json(const nlohmann::json& j) {
  AssetReport r;
  r.mesh = j.at("mesh").get<std::string>();
  r.source_path = j.at("source_path").get<std::string>();
  r.build_id = j.at("build_id").get<std::string>();
  r.inputs = j.at("inputs");
  if (BuiltMesh mesh; !built_mesh_from_inputs(r.inputs, mesh))
    throw nlohmann::json::other_error::create(501, "no record of its mesh (inputs.mesh)", &j);
  r.mesh_part = j.value("mesh_part", std::string());
  r.mesh_modified_ns = j.value("mesh_modified_ns", std::int64_t(0));
  r.warnings = j.at("warnings").get<std::vector<std::string>>();
  r.topology = topology_from_json(j.at("topology"));
  const nlohmann::json& image = j.at("geometry_image");
  r.geometry_image = geometry_image_report_from_json(image);
  r.image_size = image.at("size").get<int>();
  r.image_write_seconds = image.at("write_seconds").get<double>();
  r.box = box_from_json(j.at("box"));
  const nlohmann::json& field = j.at("geometry_field");
  r.geometry_field = field_file_report_from_json(field);
  r.geometry_field.image_size = r.image_size;
  r.field_precision = field.at("precision").get<std::string>() == "half" ? ExrPrecision::kHalf
                                                                         : ExrPrecision::kFloat;
  if (j.contains("accuracy"))
    r.accuracy = verify_report_from_json(j["accuracy"]);
  const nlohmann::json& files = j.at("files");
  r.files.image = files.at("geometry_image").get<std::string>();
  r.files.parameterized_mesh = files.at("parameterized_mesh").get<std::string>();
  r.files.field = files.at("geometry_field").get<std::string>();
  r.image_file_bytes = files.at("geometry_image_bytes").get<size_t>();
  r.stage_seconds = stage_seconds_from_json(j.at("stage_seconds"));
  r.seconds = j.at("seconds").get<double>();
  return r;
}

bool read_asset_report(const std::string& file, AssetReport& report, std::string& error) {
  nlohmann::json j;
  if (!read_report_json(file, j, error))
    return false;
  try {
    report = asset_report_from_json(j);
  } catch (const nlohmann::json::exception& e) {
    const std::string what = e.what();  // "[json.exception.KIND.ID] what is wrong"
    error = file + ": not an asset report (" + what.substr(what.find("] ") + 2) + ")";
    return false;
  }
  return true;
}

}  // namespace gfield
