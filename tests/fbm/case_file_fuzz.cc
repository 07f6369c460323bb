// Fuzzing the case-file and particle-file readers: random mutations of every
// shipped case file (and of a particle file) go through what
// `particulate --validate` does (read_case_file, check_case_against_mesh).
// Each must either be refused with a std::runtime_error whose message names
// the file, or be accepted with values a run can use (finite, positive
// where physical, particles inside the box). Nothing may crash, hang, run
// out of memory or throw anything else.
//
// Usage: fbm_case_file_fuzz CASE_DIR PARTICLE_SET_DIR [mutations per file]
//        [seed]
//   CASE_DIR          every *.prm below it is mutated (prm/)
//   PARTICLE_SET_DIR  a case with a particle file, which is mutated too
// The mutations of a case are written next to it as _fuzz_<pid>.prm, so
// that the files it names by relative paths (surface meshes, CGAL's sample
// meshes in the build folder) are found as from the original; a case that
// crashes or hangs is left there. A case with more than two surface-mesh
// shapes gets a quarter of the mutations: reading and checking its meshes
// takes seconds per mutation. The particle file's mutations are written to
// the temporary folder printed at the start.
#include <particulate/fbm/case_file.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <regex>

#include <sys/resource.h>
#include <unistd.h>

using namespace particulate;
namespace fs = std::filesystem;

namespace {
  int failures = 0;

  void
  check(const bool ok, const std::string &what)
  {
    if (!ok)
      {
        std::cerr << "FAILED: " << what << std::endl;
        ++failures;
      }
  }

  std::string
  slurp(const fs::path &path)
  {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
  }

  std::vector<std::string>
  lines_of(const std::string &text)
  {
    std::vector<std::string> lines;
    std::string              line;
    std::istringstream       in(text);
    while (std::getline(in, line))
      lines.push_back(line);
    return lines;
  }

  std::string
  joined(const std::vector<std::string> &lines)
  {
    std::string text;
    for (const auto &l : lines)
      text += l + "\n";
    return text;
  }

  /** Values no entry should take without a word. */
  const std::vector<std::string> hostile_values = {"-1",
                                                   "0",
                                                   "-0",
                                                   "1e308",
                                                   "-1e308",
                                                   "1e400",
                                                   "nan",
                                                   "inf",
                                                   "-inf",
                                                   "",
                                                   "abc",
                                                   "1e-308",
                                                   "4294967296",
                                                   "99999999999",
                                                   "3.5e",
                                                   "1,2",
                                                   "0x10",
                                                   "1 2 3",
                                                   "2,",
                                                   "-2147483649",
                                                   "12",
                                                   "100000",
                                                   "1000, 1000, 1000",
                                                   "1e-310"};

  /** A value that is the old one scaled, shifted or shortened. */
  std::string
  nudged(const std::string &value, std::mt19937 &rng)
  {
    const auto parts
      = lines_of(std::regex_replace(value, std::regex(","), "\n"));
    switch (rng() % 5)
      {
        case 0: // drop the last component of a list
          return value.substr(0, value.rfind(','));
        case 1: // add a component
          return value + ", 1";
        default:
          {
            static const double factors[] = {-1., 1e6, 1e-6, 1e12, 0.};
            const double        f         = factors[rng() % 5];
            std::string         out;
            for (const auto &p : parts)
              {
                char        *end = nullptr;
                const double v   = std::strtod(p.c_str(), &end);
                std::string  q   = p;
                if (end != p.c_str())
                  {
                    std::ostringstream s;
                    s << v * f;
                    q = s.str();
                  }
                out += (out.empty() ? "" : ",") + q;
              }
            return out;
          }
      }
  }

  /** One mutation of the lines of a case file. */
  void
  mutate_once(std::vector<std::string>       &lines,
              const std::vector<std::string> &all_values,
              std::mt19937                   &rng)
  {
    if (lines.empty())
      return;
    static const std::regex set_line(R"(^(\s*set\s+[^=]+=\s*)(.*)$)");
    const std::size_t       i = rng() % lines.size();
    std::smatch             m;
    const bool              is_set = std::regex_match(lines[i], m, set_line);
    switch (rng() % 10)
      {
        case 0:
        case 1:
        case 2: // a hostile value
          if (is_set)
            lines[i]
              = m[1].str() + hostile_values[rng() % hostile_values.size()];
          break;
        case 3:
        case 4: // the value scaled or a component more or less
          if (is_set)
            lines[i] = m[1].str() + nudged(m[2].str(), rng);
          break;
        case 5: // another entry's value
          if (is_set && !all_values.empty())
            lines[i] = m[1].str() + all_values[rng() % all_values.size()];
          break;
        case 6: // a line deleted
          lines.erase(lines.begin() + i);
          break;
        case 7: // a line duplicated
          lines.insert(lines.begin() + i, lines[i]);
          break;
        case 8: // two lines swapped, or an 'end' / 'subsection' too many
          if (rng() % 2)
            std::swap(lines[i], lines[rng() % lines.size()]);
          else
            lines.insert(lines.begin() + i,
                         rng() % 2 ? "end" : "subsection Particles");
          break;
        default: // bytes: flipped, or the file cut
          {
            std::string &l = lines[i];
            if (rng() % 4 == 0)
              lines.resize(i);
            else if (!l.empty())
              l[rng() % l.size()] = static_cast<char>(rng() % 256);
          }
      }
  }

  /** What a run needs of an accepted case, checked apart from the reader. */
  std::string
  unusable_value(const fbm::ParticulateFlowParameters &p)
  {
    const auto &time  = p.flow.time;
    const auto &fluid = p.flow.fluid.properties;
    if (!(std::isfinite(time.time_step) && time.time_step > 0.))
      return "time step " + std::to_string(time.time_step);
    if (!(std::isfinite(time.end_time) && time.end_time >= 0.))
      return "end time " + std::to_string(time.end_time);
    if (!(std::isfinite(fluid.density) && fluid.density > 0.))
      return "fluid density " + std::to_string(fluid.density);
    if (!(std::isfinite(fluid.dynamic_viscosity)
          && fluid.dynamic_viscosity > 0.))
      return "viscosity " + std::to_string(fluid.dynamic_viscosity);
    for (std::size_t d = 0; d < p.flow.mesh.lower_corner.size()
                            && d < p.flow.mesh.upper_corner.size();
         ++d)
      if (!(p.flow.mesh.lower_corner[d] < p.flow.mesh.upper_corner[d]))
        return "mesh corners in direction " + std::to_string(d);
    for (const auto &b : p.particles.bodies)
      {
        const double volume = b.shape ? b.shape->volume() : 0.;
        if (!(std::isfinite(volume) && volume > 0.))
          return b.origin + ": particle volume " + std::to_string(volume);
        if (!(std::isfinite(b.density) && b.density > 0.))
          return b.origin + ": particle density " + std::to_string(b.density);
        if (!b.position.allFinite() || !b.velocity.allFinite()
            || !b.angular_velocity.allFinite())
          return b.origin + ": a position or velocity is not finite";
        if (!(std::abs(b.orientation.norm() - 1.) < 1e-9))
          return b.origin + ": orientation not a unit quaternion";
      }
    return "";
  }

  struct Counts
  {
    long                        accepted = 0, refused = 0;
    std::map<std::string, long> refused_by_file;
  };

  fs::path    current_case;
  std::string current_origin;

  void
  on_alarm(int)
  {
    const std::string message
      = "\nfuzz: a case took more than 60 s (hang): " + current_origin
        + ", kept as " + current_case.string() + "\n";
    [[maybe_unused]] auto n = ::write(2, message.data(), message.size());
    std::_Exit(2);
  }

  /** How many of the lines of @p lines give a shape the type mesh. */
  unsigned int
  mesh_shapes(const std::vector<std::string> &lines)
  {
    static const std::regex mesh_type(R"(^\s*set\s+Type\s*=\s*mesh\s*$)");
    return std::count_if(lines.begin(), lines.end(), [](const std::string &l) {
      return std::regex_match(l, mesh_type);
    });
  }

  /** Read and check the case at @p path as --validate does. */
  void
  validate(const fs::path    &path,
           Counts            &counts,
           const std::string &origin,
           const std::string &other_file = "")
  {
    current_origin             = origin;
    const std::string filename = path.string();
    ::alarm(60);
    try
      {
        dealii::ParameterHandler prm;
        const auto parameters = fbm::read_case_file(prm, filename);
        fbm::check_case_against_mesh(parameters, filename, MPI_COMM_WORLD);
        const std::string bad = unusable_value(parameters);
        check(bad.empty(),
              origin + ": accepted with an unusable value: " + bad
                + "\n--- case ---\n" + slurp(path));
        ++counts.accepted;
      }
    catch (const std::runtime_error &e)
      {
        const std::string message = e.what();
        check(message.find(filename) != std::string::npos
                || (!other_file.empty()
                    && message.find(other_file) != std::string::npos),
              origin + ": refused without naming the file: " + message);
        ++counts.refused;
        ++counts.refused_by_file[origin.substr(0, origin.find('#'))];
      }
    catch (const std::exception &e)
      {
        check(false,
              origin + ": refused by an unexpected exception ("
                + typeid(e).name() + "): " + e.what() + "\n--- case ---\n"
                + slurp(path));
      }
    ::alarm(0);
  }

  std::vector<std::string>
  values_of(const std::vector<std::string> &lines)
  {
    static const std::regex  set_line(R"(^\s*set\s+[^=]+=\s*(.*)$)");
    std::vector<std::string> values;
    std::smatch              m;
    for (const auto &l : lines)
      if (std::regex_match(l, m, set_line))
        values.push_back(m[1].str());
    return values;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 3)
    {
      std::cerr << "usage: fbm_case_file_fuzz CASE_DIR PARTICLE_SET_DIR "
                   "[mutations per file] [seed]\n";
      return 1;
    }
  const fs::path case_dir     = argv[1];
  const fs::path particle_dir = argv[2];
  const int      per_file     = argc > 3 ? std::atoi(argv[3]) : 40;
  std::mt19937   rng(argc > 4 ? std::atoi(argv[4]) : 2024);

  // An entry that asks for a huge mesh or particle count must be refused,
  // not allocated until the machine swaps: beyond 8 GiB the allocation
  // fails and the test reports the case.
  const rlimit memory{8ul << 30, 8ul << 30};
  setrlimit(RLIMIT_AS, &memory);
  std::signal(SIGALRM, on_alarm);

  const fs::path tmp
    = fs::temp_directory_path()
      / ("particulate_case_fuzz_" + std::to_string(::getpid()));
  fs::create_directories(tmp);
  std::cout << "fuzz: mutated cases are written next to each case as "
               "_fuzz_"
            << ::getpid() << ".prm, particle files to " << tmp << std::endl;

  std::vector<fs::path> cases;
  // not the temporary copies that a running validation test or fuzz writes
  // next to a case (tests/validation/run_case_and_check.sh, this test); they
  // come and go
  for (const auto &entry : fs::recursive_directory_iterator(case_dir))
    if (entry.path().extension() == ".prm"
        && entry.path().filename().string().rfind("_validation_", 0) != 0
        && entry.path().filename().string().rfind("_fuzz_", 0) != 0)
      cases.push_back(entry.path());
  std::sort(cases.begin(), cases.end());
  check(!cases.empty(), "no .prm files below " + case_dir.string());

  Counts counts;
  for (const fs::path &original : cases)
    {
      current_case = original.parent_path()
                     / ("_fuzz_" + std::to_string(::getpid()) + ".prm");
      // the shipped file itself must be accepted
      fs::copy_file(original,
                    current_case,
                    fs::copy_options::overwrite_existing);
      Counts shipped;
      validate(current_case, shipped, original.string() + " (as shipped)");
      check(shipped.accepted == 1, original.string() + " is refused");

      const auto lines     = lines_of(slurp(original));
      const auto values    = values_of(lines);
      const int  mutations = mesh_shapes(lines) > 2 ? per_file / 4 : per_file;
      for (int c = 0; c < mutations; ++c)
        {
          auto mutated = lines;
          for (unsigned int n = 1 + rng() % 3; n > 0; --n)
            mutate_once(mutated, values, rng);
          std::ofstream(current_case, std::ios::trunc) << joined(mutated);
          validate(current_case,
                   counts,
                   original.filename().string() + "#" + std::to_string(c));
        }
      if (failures == 0)
        fs::remove(current_case);
    }

  // The particle file: its case and file copied, the file mutated.
  current_case                 = tmp / "current.prm";
  const fs::path particle_case = particle_dir / "mixed_set.prm";
  const fs::path particle_file = particle_dir / "mixed_set_particles.csv";
  fs::copy_file(particle_case,
                current_case,
                fs::copy_options::overwrite_existing);
  const auto               particle_lines = lines_of(slurp(particle_file));
  std::vector<std::string> particle_values;
  for (const auto &l : particle_lines)
    for (const auto &v :
         lines_of(std::regex_replace(l, std::regex("[, ]+"), "\n")))
      particle_values.push_back(v);
  Counts particles;
  for (int c = 0; c < 10 * per_file; ++c)
    {
      auto mutated = particle_lines;
      for (unsigned int n = 1 + rng() % 3; n > 0 && !mutated.empty(); --n)
        {
          const std::size_t i      = rng() % mutated.size();
          auto              fields = lines_of(
            std::regex_replace(mutated[i], std::regex("[, ]+"), "\n"));
          if (rng() % 3 == 0 || fields.empty())
            mutate_once(mutated, particle_values, rng);
          else
            {
              // one value of a line replaced by a hostile or another value
              auto &f = fields[rng() % fields.size()];
              f = rng() % 2 ? hostile_values[rng() % hostile_values.size()] :
                              particle_values[rng() % particle_values.size()];
              std::string line;
              for (const auto &x : fields)
                line += (line.empty() ? "" : ", ") + x;
              mutated[i] = line;
            }
        }
      std::ofstream(tmp / particle_file.filename(), std::ios::trunc)
        << joined(mutated);
      validate(current_case,
               particles,
               "particle file#" + std::to_string(c),
               (tmp / particle_file.filename()).string());
    }

  std::cout << "fuzz: " << cases.size() << " case files, "
            << counts.accepted + counts.refused
            << " mutations: " << counts.refused
            << " refused with a message naming the file, " << counts.accepted
            << " accepted with usable values\n"
            << "fuzz: particle file, " << particles.accepted + particles.refused
            << " mutations: " << particles.refused << " refused, "
            << particles.accepted << " accepted" << std::endl;
  if (failures == 0)
    fs::remove_all(tmp);
  std::cout << (failures == 0 ? "PASSED" : "FAILED") << std::endl;
  return failures == 0 ? 0 : 1;
}
