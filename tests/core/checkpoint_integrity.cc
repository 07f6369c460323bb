// A checkpoint proves itself before a restart reads it (2 ranks):
// - a saved checkpoint loads back what was written, and a second save
//   replaces the first;
// - a rank file with a few bytes changed in its data, a truncated one, one
//   of another format version (also the old format 1), one written by
//   another number of ranks and data left unread are each refused on every
//   rank with a message that names the file and the cause (no rank is left
//   waiting in a collective read);
// - a save cut off between the two renames of its swap leaves the previous
//   checkpoint in checkpoint.old/, and a restart finds it there.

#include <particulate/core/checkpoint.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

using namespace particulate;

namespace {
  namespace fs = std::filesystem;

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

  /** The data this rank saves in checkpoint number @p version. */
  std::vector<double>
  rank_data(const unsigned int rank, const unsigned int version)
  {
    std::vector<double> values(1000);
    for (unsigned int i = 0; i < values.size(); ++i)
      values[i] = 1000. * version + rank + 1e-3 * i;
    return values;
  }

  void
  save(const core::Checkpoint &checkpoint,
       const unsigned int      rank,
       const unsigned int      version)
  {
    checkpoint.save(
      [&](std::ostream &out) {
        core::write_binary_vector(out, rank_data(rank, version));
      },
      version,
      version);
  }

  std::vector<double>
  load(const core::Checkpoint &checkpoint)
  {
    std::vector<double> values;
    checkpoint.load(
      [&](std::istream &in) { values = core::read_binary_vector<double>(in); });
    return values;
  }

  /** The message load() throws, or "" if it loads. */
  std::string
  load_error(const core::Checkpoint                    &checkpoint,
             const std::function<void(std::istream &)> &reader)
  {
    try
      {
        checkpoint.load(reader);
      }
    catch (const std::runtime_error &e)
      {
        return e.what();
      }
    return "";
  }

  std::string
  load_error(const core::Checkpoint &checkpoint)
  {
    return load_error(checkpoint, [](std::istream &in) {
      core::read_binary_vector<double>(in);
    });
  }

  /** Overwrites bytes of @p file at @p offset (0: the middle). */
  void
  overwrite(const std::string &file,
            std::streamoff     offset,
            const std::string &bytes)
  {
    if (offset == 0)
      offset = fs::file_size(file) / 2;
    std::fstream f(file, std::ios::binary | std::ios::in | std::ios::out);
    f.seekp(offset);
    f.write(bytes.data(), bytes.size());
  }

  /** Runs @p damage on rank 0 against a fresh checkpoint, then requires
   *  every rank's load() to be refused with a message containing each of
   *  @p expected. */
  void
  check_refused(const core::Checkpoint         &checkpoint,
                MPI_Comm                        comm,
                const std::string              &what,
                const std::function<void()>    &damage,
                const std::vector<std::string> &expected)
  {
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    save(checkpoint, rank, 7);
    if (rank == 0)
      damage();
    MPI_Barrier(comm);
    const std::string message = load_error(checkpoint);
    if (rank == 0)
      std::cout << what << ": " << message << std::endl;
    check(!message.empty(),
          what + ": accepted on rank " + std::to_string(rank));
    for (const std::string &e : expected)
      check(message.find(e) != std::string::npos,
            what + ": the message on rank " + std::to_string(rank)
              + " does not say '" + e + "': " + message);
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPI_Comm                                 comm = MPI_COMM_WORLD;
  const unsigned int rank   = dealii::Utilities::MPI::this_mpi_process(comm);
  const std::string  output = "checkpoint_integrity_output";
  if (rank == 0)
    {
      fs::remove_all(output);
      fs::create_directories(output);
    }
  MPI_Barrier(comm);
  const core::Checkpoint checkpoint(output, comm);
  const std::string      folder = checkpoint.directory();

  check(!checkpoint.exists(), "a checkpoint exists before the first save");
  save(checkpoint, rank, 1);
  check(load(checkpoint) == rank_data(rank, 1), "the first save loads back");
  save(checkpoint, rank, 2);
  check(load(checkpoint) == rank_data(rank, 2),
        "the second save replaces the first");
  check(!fs::exists(folder + ".new") && !fs::exists(folder + ".old"),
        "a finished save leaves checkpoint.new or checkpoint.old behind");

  // a byte of the data changed in the middle of rank 1's file
  check_refused(checkpoint,
                comm,
                "corrupted",
                [&]() { overwrite(folder + "/rank-1.bin", 0, "XYZ"); },
                {"rank-1.bin", "checksum", "corrupted"});
  check_refused(checkpoint,
                comm,
                "truncated",
                [&]() {
                  fs::resize_file(folder + "/rank-0.bin",
                                  fs::file_size(folder + "/rank-0.bin") - 100);
                },
                {"rank-0.bin", "not as long as its header says"});
  // the format version follows the magic string (its length, 8 bytes, and
  // 22 characters)
  check_refused(checkpoint,
                comm,
                "another format version",
                [&]() {
                  std::string version(sizeof(unsigned int), '\0');
                  version[0] = 99;
                  overwrite(folder + "/rank-0.bin", 30, version);
                },
                {"rank-0.bin", "format 99", "reads format"});
  check_refused(checkpoint,
                comm,
                "format 1",
                [&]() {
                  std::ofstream out(folder + "/rank-1.bin", std::ios::binary);
                  core::write_binary_string(out, "PARTICULATE-CHECKPOINT-1");
                  core::write_binary<unsigned int>(out, 2);
                  core::write_binary<unsigned int>(out, 1);
                },
                {"rank-1.bin", "format 1"});
  check_refused(checkpoint,
                comm,
                "not a checkpoint",
                [&]() {
                  std::ofstream out(folder + "/rank-0.bin", std::ios::binary);
                  out << "some other file, long enough to hold a header";
                },
                {"rank-0.bin", "not a Particulate checkpoint"});

  // data that the reader leaves unread
  save(checkpoint, rank, 3);
  const std::string unread = load_error(checkpoint, [](std::istream &in) {
    core::read_binary<unsigned long>(in);
  });
  check(unread.find("more data than this version") != std::string::npos,
        "unread data: " + unread);

  // a save cut off after the current checkpoint was renamed to
  // checkpoint.old and before checkpoint.new took its place
  save(checkpoint, rank, 4);
  MPI_Barrier(comm);
  if (rank == 0)
    fs::rename(folder, folder + ".old");
  MPI_Barrier(comm);
  check(checkpoint.exists(), "the checkpoint in checkpoint.old is not found");
  check(load(checkpoint) == rank_data(rank, 4),
        "the checkpoint in checkpoint.old does not load back");
  save(checkpoint, rank, 5);
  check(load(checkpoint) == rank_data(rank, 5) && !fs::exists(folder + ".old"),
        "a save after the cut-off one replaces both");

  // a checkpoint of 2 ranks read by 1
  if (dealii::Utilities::MPI::n_mpi_processes(comm) == 2)
    {
      MPI_Comm alone;
      MPI_Comm_split(comm, rank, 0, &alone);
      if (rank == 0)
        {
          const std::string message
            = load_error(core::Checkpoint(output, alone));
          std::cout << "fewer ranks: " << message << std::endl;
          check(message.find("mpirun -np 2") != std::string::npos,
                "fewer ranks: " + message);
        }
      MPI_Comm_free(&alone);
    }

  const int all_failures = dealii::Utilities::MPI::sum(failures, comm);
  if (rank == 0)
    std::cout << (all_failures == 0 ? "OK" : "FAILED") << std::endl;
  return all_failures == 0 ? 0 : 1;
}
