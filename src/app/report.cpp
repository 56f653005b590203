// SPDX-License-Identifier: MIT
// `silodem report DIR` and `silodem compare DIR...`: figures (PNG) and report.html, made by the
// post-processing scripts in tools/ with a Python that imports matplotlib. The interpreter is the
// one found when the build was configured, or $SILODEM_PYTHON; the scripts' folder is the source
// tree's tools/, or $SILODEM_TOOLS.
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <cstdlib>
#include <filesystem>

#include "app/commands.hpp"
#include "core/error.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace silodem::app {
namespace {

std::string env_or(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : std::string(fallback);
}

// Runs argv[0] with the arguments; returns its exit code (-1 if it could not start).
int spawn(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Tools {
  std::string python, dir, problem;  // problem: why figures cannot be made (empty = fine)
};

Tools find_tools() {
  Tools t{env_or("SILODEM_PYTHON", SILODEM_PYTHON), env_or("SILODEM_TOOLS", SILODEM_TOOLS_DIR), {}};
  if (t.python.empty())
    t.problem =
        "no Python with matplotlib was found when silodem was built (install "
        "python3-matplotlib and rebuild, or set SILODEM_PYTHON)";
  else if (!fs::exists(fs::path(t.dir) / "silodem_report.py"))
    t.problem =
        fmt::format("the post-processing scripts are not in '{}' (set SILODEM_TOOLS)", t.dir);
  return t;
}

}  // namespace

int run_tool(const std::string& script, const std::vector<std::string>& args,
             bool quiet_if_unavailable) {
  const Tools t = find_tools();
  if (!t.problem.empty()) {
    if (quiet_if_unavailable) {
      fmt::print(stderr, "warning: figures and report.html not made: {}\n", t.problem);
      return kExitOk;
    }
    throw std::runtime_error(t.problem);
  }
  std::vector<std::string> argv = {t.python, (fs::path(t.dir) / script).string()};
  argv.insert(argv.end(), args.begin(), args.end());
  const int rc = spawn(argv);
  if (rc != 0) {
    fmt::print(stderr, "error: {} failed (exit {})\n", script, rc);
    return rc == 2 ? kExitInput : 1;
  }
  return kExitOk;
}

namespace {
void require_run_dir(const std::string& dir) {
  if (!fs::is_regular_file(fs::path(dir) / "summary.json"))
    throw InputError({}, "DIR", fmt::format("'{}' has no summary.json: not a run directory", dir));
}
}  // namespace

int report_command(const std::string& dir, bool quiet_if_unavailable) {
  if (find_tools().problem.empty()) require_run_dir(dir);
  return run_tool("silodem_report.py", {dir}, quiet_if_unavailable);
}

int compare_command(const std::vector<std::string>& dirs, const std::string& out,
                    const std::string& labels) {
  if (const Tools t = find_tools(); !t.problem.empty()) throw std::runtime_error(t.problem);
  if (dirs.size() < 2) throw InputError({}, "DIR", "compare needs at least two run directories");
  for (const auto& d : dirs) require_run_dir(d);
  std::vector<std::string> args = {"--out", out};
  if (!labels.empty()) args.insert(args.end(), {"--labels", labels});
  args.insert(args.end(), dirs.begin(), dirs.end());
  return run_tool("silodem_compare.py", args, false);
}

}  // namespace silodem::app
