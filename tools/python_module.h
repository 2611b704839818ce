// Parts of the command line that live in the Python package (the Dask driver, the viewer's
// server): run `$VRS_PYTHON -m MODULE ARGS...` in this process (the console script sets
// VRS_PYTHON to its own Python; else python3).
#pragma once

#include <string>
#include <vector>

namespace vrs_tool {

// Does not return when the module starts; else prints "vrsimplify: `what` needs the Python
// package (`install`): cannot run PYTHON" and returns 1.
int exec_python_module(const char* module, const std::vector<std::string>& args, const char* what,
                       const char* install);

} // namespace vrs_tool
