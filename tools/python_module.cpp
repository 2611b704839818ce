#include "python_module.h"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace vrs_tool {

int exec_python_module(const char* module, const std::vector<std::string>& args, const char* what,
                       const char* install) {
  const char* python = std::getenv("VRS_PYTHON");
  if (!python || !*python) python = "python3";
  std::vector<const char*> argv = {python, "-m", module};
  for (const std::string& a : args)
    argv.push_back(a.c_str());
  argv.push_back(nullptr);
  execvp(python, const_cast<char* const*>(argv.data()));
  std::fprintf(stderr, "vrsimplify: %s needs the Python package (%s): cannot run %s\n", what,
               install, python);
  return 1;
}

} // namespace vrs_tool
