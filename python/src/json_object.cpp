#include "python/src/json_object.hpp"

namespace gfield::python {
namespace {

/// `text` as str, each byte that is not part of valid UTF-8 as a \xNN escape.
py::object text_object(const std::string& text) {
  PyObject* object =
      PyUnicode_DecodeUTF8(text.data(), py::ssize_t(text.size()), "backslashreplace");
  if (object == nullptr) {
    throw py::error_already_set();
  }
  return py::reinterpret_steal<py::object>(object);
}

}  // namespace

py::object json_to_python(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) {
        dict[text_object(key)] = json_to_python(item);
      }
      return dict;
    }
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const nlohmann::json& item : value) {
        list.append(json_to_python(item));
      }
      return list;
    }
    case nlohmann::json::value_t::string:
      return text_object(value.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(value.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(value.get<double>());
    default:
      return py::none();
  }
}

}  // namespace gfield::python
