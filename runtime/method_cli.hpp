#pragma once
// The methods' options on gfield-view's command line: one `--NAME` per option name, made from
// the methods' MethodOption descriptions. An option that several methods declare (e.g.
// --buffer-scale of wyman2005 and davis-wyman) is one command-line option that sets all of
// them; its group lists the methods it applies to. Compiled into gfield-view (CLI11).

#include <vector>

#include <CLI/CLI.hpp>

#include "runtime/method.hpp"

namespace gfield {

/// Adds the options of `methods` to `app`, bound to the methods' own variables.
void add_method_options(CLI::App& app, const std::vector<Method*>& methods);

}  // namespace gfield
