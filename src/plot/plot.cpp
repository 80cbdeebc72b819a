#include "stratum/plot.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <algorithm>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

#include "stratum/distributed.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/plot_scripts.hpp"
#include "stratum/util/error.hpp"

namespace stratum::plot {

namespace {

std::string_view find_script(std::string_view name) {
  for (const auto& [key, text] : plot_scripts)
    if (key == name) return text;
  throw std::logic_error("no plot script named " + std::string(name));
}

/// A file removed when it goes out of scope (unless released).
struct TemporaryFile {
  std::string path;
  ~TemporaryFile() {
    if (!path.empty()) std::remove(path.c_str());
  }
};

std::string make_temporary(const std::string& pattern_prefix, const std::string& suffix) {
  std::string pattern = pattern_prefix + "XXXXXX" + suffix;
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const int fd = mkstemps(buffer.data(), static_cast<int>(suffix.size()));
  if (fd < 0) return {};
  close(fd);
  return std::string(buffer.data());
}

pid_t start_python(const std::vector<std::string>& arguments) {
  const char* configured = std::getenv("STRATUM_PYTHON");
  const std::string python = configured && *configured ? configured : "/usr/bin/python3";
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(python.c_str()));
  for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error(std::string("plot: cannot start Python: ") + std::strerror(errno));
  if (child == 0) {
    execv(python.c_str(), argv.data());
    std::fprintf(stderr, "stratum: cannot run %s: %s\n", python.c_str(), std::strerror(errno));
    _exit(127);
  }
  return child;
}

int wait_python(pid_t child) {
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("plot: lost the Python process");
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// Runs a list of plot jobs in one interpreter, so matplotlib is imported
/// once: argv[1] is a JSON list of {script, data, out}.
constexpr std::string_view batch_driver = R"stratum_py(
import json, runpy, sys, traceback
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.figure, matplotlib.text
# Every PNG records the smallest font it drew, in pixels of the image
# (point size x dpi / 72), as the text chunk "stratum:min-font-px": the report's
# browser test scales it by the displayed width to check legibility.
_drawn_sizes = []
_text_draw = matplotlib.text.Text.draw
def _recording_draw(self, renderer):
    if self.get_visible() and self.get_text().strip():
        _drawn_sizes.append(self.get_fontsize())
    return _text_draw(self, renderer)
matplotlib.text.Text.draw = _recording_draw
_savefig = matplotlib.figure.Figure.savefig
def _savefig_with_font_size(self, fname, *args, **kwargs):
    if str(fname).lower().endswith(".png"):
        dpi = kwargs.get("dpi", "figure")
        dpi = self.dpi if dpi in (None, "figure") else dpi
        _drawn_sizes.clear()
        self.canvas.draw()
        if _drawn_sizes:
            metadata = dict(kwargs.pop("metadata", None) or {})
            metadata["stratum:min-font-px"] = "%.3f" % (min(_drawn_sizes) * dpi / 72)
            kwargs["metadata"] = metadata
    return _savefig(self, fname, *args, **kwargs)
matplotlib.figure.Figure.savefig = _savefig_with_font_size
failed = 0
for job in json.load(open(sys.argv[1])):
    sys.argv = [job["script"], job["data"], job["out"]]
    try:
        runpy.run_path(job["script"], run_name="__main__")
    except SystemExit as e:
        failed += e.code not in (0, None)
    except OSError as e:  # a full disk, a lost folder: the user's problem, said in one line, not a traceback
        print("stratum: error: cannot write the figure %s: %s" % (job.get("target", job["out"]), e.strerror or e),
              file=sys.stderr)
        failed += 1
    except Exception:
        traceback.print_exc()
        failed += 1
    plt.close("all")
sys.exit(1 if failed else 0)
)stratum_py";

/// Writes a temporary input file of the plot, checked.
void write_temporary(const std::string& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("plot: cannot write the temporary file " + path + " (no room on the disk?)");
}

/// The temporary files of one job: its script and its data (in the
/// temporary folder) and its figure (the staging file of its output).
struct StagedJob {
  std::string script_name;
  std::string target;
  std::unique_ptr<io::OutputFile> own;  // when the job brought no prepared output
  io::OutputFile* figure = nullptr;
  TemporaryFile code, json;
};

std::unique_ptr<StagedJob> stage(const PlotJob& job) {
  namespace fs = std::filesystem;
  const std::string_view text = find_script(job.script);
  auto staged = std::make_unique<StagedJob>();
  staged->script_name = job.script;
  staged->target = job.png;
  staged->figure = job.output;
  if (!staged->figure) {
    staged->own = std::make_unique<io::OutputFile>("plot", job.png);
    staged->figure = staged->own.get();
  }
  staged->figure->prepare();
  const std::string temp_dir = fs::temp_directory_path().string();
  staged->json.path = make_temporary(temp_dir + "/stratum-plot-", ".json");
  staged->code.path = make_temporary(temp_dir + "/stratum-plot-", ".py");
  if (staged->json.path.empty() || staged->code.path.empty())
    throw std::runtime_error("plot: cannot create temporary files in " + temp_dir);
  write_temporary(staged->json.path, job.data.dump());
  write_temporary(staged->code.path, text);
  return staged;
}

}  // namespace

std::unique_ptr<io::OutputFile> prepare_plot(const std::string& argument, const std::string& png) {
  if (png.empty()) return nullptr;
  auto output = std::make_unique<io::OutputFile>(argument, png);
  output->prepare();
  return output;
}

void write_plot(std::string_view script, const nlohmann::json& data, const std::string& png) {
  write_plots({PlotJob{std::string(script), data, png}}, 1);
}

void write_plot(std::string_view script, const nlohmann::json& data, io::OutputFile& png) {
  write_plots({PlotJob{std::string(script), data, png.path(), &png}}, 1);
}

void write_plots(const std::vector<PlotJob>& jobs, unsigned processes) {
  namespace fs = std::filesystem;
  if (jobs.empty() || !distributed::is_root()) return;  // a distributed job draws once, on rank 0
  std::vector<std::unique_ptr<StagedJob>> staged;
  for (const auto& job : jobs) staged.push_back(stage(job));
  processes = std::max(1u, std::min<unsigned>(processes, static_cast<unsigned>(jobs.size())));
  // Job i goes to process i mod P; each process gets a list file and the driver.
  const std::string temp_dir = fs::temp_directory_path().string();
  TemporaryFile driver{make_temporary(temp_dir + "/stratum-plot-", ".py")};
  if (driver.path.empty()) throw std::runtime_error("plot: cannot create temporary files in " + temp_dir);
  write_temporary(driver.path, batch_driver);
  std::vector<TemporaryFile> lists(processes);
  std::vector<pid_t> children;
  for (unsigned p = 0; p < processes; ++p) {
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t i = p; i < staged.size(); i += processes)
      list.push_back({{"script", staged[i]->code.path},
                      {"data", staged[i]->json.path},
                      {"out", staged[i]->figure->staging()},
                      {"target", staged[i]->target}});
    lists[p].path = make_temporary(temp_dir + "/stratum-plot-", ".json");
    if (lists[p].path.empty()) throw std::runtime_error("plot: cannot create temporary files in " + temp_dir);
    write_temporary(lists[p].path, list.dump());
  }
  for (unsigned p = 0; p < processes; ++p) children.push_back(start_python({driver.path, lists[p].path}));
  int worst = 0;
  for (const pid_t child : children) worst = std::max(worst, wait_python(child));
  for (const auto& job : staged) {
    std::error_code error;
    if (fs::file_size(job->figure->staging(), error) == 0 || error)
      throw std::runtime_error("plot: the matplotlib script '" + job->script_name + "' failed (exit status " +
                               std::to_string(worst) + "); no figure written for " + job->target);
  }
  if (worst != 0) throw std::runtime_error("plot: Python exited with status " + std::to_string(worst));
  for (auto& job : staged) job->figure->check_staged();
  // All figures in place, or none: a failure removes those put in place before it.
  for (std::size_t i = 0; i < staged.size(); ++i) {
    try {
      staged[i]->figure->commit();
    } catch (...) {
      for (std::size_t j = 0; j < i; ++j) staged[j]->figure->remove_committed();
      throw;
    }
  }
}

}  // namespace stratum::plot
