#include "runtime/method_cli.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace gfield {
namespace {

/// One command-line option: its description (from the first method that declares it) and every
/// method's copy of it.
struct SharedOption {
  MethodOption first;
  std::vector<MethodOption> copies;
  std::string methods;  ///< "wyman2005, davis-wyman"
};

CLI::Option* add_shared(CLI::App& app, const SharedOption& shared) {
  const MethodOption& o = shared.first;
  const std::string flag = "--" + o.name;
  const std::vector<MethodOption> copies = shared.copies;
  switch (o.kind) {
    case MethodOption::Kind::kInt:
      return app
          .add_option_function<int>(
              flag,
              [copies](int v) {
                for (const MethodOption& c : copies)
                  *c.int_value = v;
              },
              o.help)
          ->check(CLI::Range(int(o.min), int(o.max)));
    case MethodOption::Kind::kFloat:
      return app
          .add_option_function<float>(
              flag,
              [copies](float v) {
                for (const MethodOption& c : copies)
                  *c.float_value = v;
              },
              o.help)
          ->check(CLI::Range(o.min, o.max));
    case MethodOption::Kind::kFlag:
      return app.add_flag_callback(
          flag,
          [copies] {
            for (const MethodOption& c : copies)
              *c.flag_value = c.flag_sets;
          },
          o.help);
    case MethodOption::Kind::kChoice: {
      const std::vector<std::string> choices = o.choices;
      return app
          .add_option_function<std::string>(
              flag,
              [copies, choices](const std::string& v) {
                const int index =
                    int(std::find(choices.begin(), choices.end(), v) - choices.begin());
                for (const MethodOption& c : copies)
                  c.set_choice(index);
              },
              o.help)
          ->check(CLI::IsMember(choices));
    }
  }
  return nullptr;
}

}  // namespace

void add_method_options(CLI::App& app, const std::vector<Method*>& methods) {
  std::vector<std::string> order;
  std::map<std::string, SharedOption> shared;
  for (Method* method : methods) {
    for (const MethodOption& o : method->options()) {
      auto [it, added] = shared.try_emplace(o.name);
      if (added) {
        it->second.first = o;
        order.push_back(o.name);
      }
      it->second.copies.push_back(o);
      it->second.methods += (it->second.methods.empty() ? "" : ", ") + method->info().name;
    }
  }
  for (const std::string& name : order) {
    const MethodOption& first = shared[name].first;
    CLI::Option* option =
        add_shared(app, shared[name])->group("Options of " + shared[name].methods);
    if (first.kind != MethodOption::Kind::kFlag)
      option->default_str(option_value_text(first));
  }
}

}  // namespace gfield
