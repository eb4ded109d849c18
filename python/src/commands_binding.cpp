// `python3 -m tumble ...`: the command line itself (app/cli.cpp), run in this process with the
// GIL released (a sweep's threads, a video's child processes), its output on this process's
// stdout and stderr.
#include <pybind11/stl.h>

#include <cstdio>

#include "bindings.hpp"
#include "commands.hpp"

namespace tumble::python {

void bind_commands(py::module_& m) {
  m.def(
      "run_cli",
      [](const std::vector<std::string>& argv) {
        std::vector<const char*> args;
        for (const std::string& arg : argv) args.push_back(arg.c_str());
        args.push_back(nullptr);
        int status = 0;
        {
          const py::gil_scoped_release unlocked;
          status = cli::run_cli(static_cast<int>(argv.size()), args.data());
          std::fflush(stdout);
          std::fflush(stderr);
        }
        return status;
      },
      py::arg("argv"));
}

}  // namespace tumble::python
