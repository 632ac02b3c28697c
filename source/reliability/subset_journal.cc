// The journal of Subset Simulation's model runs (reliability/subset_journal.h).
#include <poundfe/reliability/subset_journal.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/base/numbers.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/output_directory.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

namespace poundfe
{
  namespace
  {
    const char *const journal_name = "subset_runs.csv";
    const char *const columns      = "level,sample,response,completed";

    bool
    is_journal(const std::filesystem::path &path)
    {
      const std::string name = path.filename().string();
      return name == journal_name ||
             (name.rfind("subset_runs.rank", 0) == 0 && path.extension() == ".csv");
    }

    /// The first `n` characters of `line`, for a message.
    std::string
    excerpt(const std::string &line, const std::size_t n = 80)
    {
      return line.size() <= n ? line : line.substr(0, n) + "...";
    }

    /// One run of a journal line "level,sample,response,completed": whole
    /// numbers, a finite response, completed 0 or 1; nothing otherwise.
    std::optional<std::pair<std::pair<unsigned int, unsigned int>, std::pair<double, bool>>>
    parse_run(const std::string &line)
    {
      std::vector<std::string_view> fields;
      for (std::size_t start = 0;;)
        {
          const std::size_t comma = line.find(',', start);
          fields.emplace_back(std::string_view(line).substr(start, comma - start));
          if (comma == std::string::npos)
            break;
          start = comma + 1;
        }
      if (fields.size() != 4)
        return std::nullopt;
      constexpr unsigned long most = std::numeric_limits<unsigned int>::max();
      const auto level = parse_count(fields[0], most), sample = parse_count(fields[1], most),
                 completed = parse_count(fields[3], 1);
      const std::optional<double> response = parse_number(fields[2]); // finite
      if (!level || !sample || !completed || !response)
        return std::nullopt;
      return std::make_pair(std::make_pair(unsigned(*level), unsigned(*sample)),
                            std::make_pair(*response, *completed != 0));
    }

    /// The runs of a journal file after its settings line and header, read
    /// by the bounded reader of every input file (base/input_text.h: a
    /// regular file of at most 1 GiB, no NUL byte, no line over 1 MiB). A
    /// kill leaves at most its last line cut (no newline): that line is
    /// dropped. Any other line that does not read as a run, or a wrong
    /// header, is a damaged journal: InputError naming the file and the
    /// line, as is a journal of other settings.
    void
    read_journal(const std::string &file, const std::string &settings,
                 std::map<std::pair<unsigned int, unsigned int>, std::pair<double, bool>> &runs)
    {
      const std::string text = read_input_text(file, "Subset simulation journal", "Subset simulation");
      const std::string damaged = "; the journal of model runs is damaged: remove it (the runs "
                                  "it holds are run again) or choose another output directory";
      std::size_t start = 0;
      for (int line_number = 1; start < text.size(); ++line_number)
        {
          const std::size_t end = text.find('\n', start);
          if (end == std::string::npos)
            break; // cut by a kill
          const std::string line = text.substr(start, end - start);
          start                  = end + 1;
          if (line_number == 1 && line != settings)
            throw InputError(file, 1, "Subset simulation",
                             "holds the model runs of other settings (" + excerpt(line, 300) +
                               "; this input: " + settings +
                               "); remove it or choose another output directory");
          if (line_number == 2 && line != columns)
            throw InputError(file, 2, "Subset simulation",
                             "expected the header '" + std::string(columns) + "', got '" +
                               excerpt(line) + "'" + damaged);
          if (line_number <= 2)
            continue;
          const auto run = parse_run(line);
          if (!run)
            throw InputError(file, line_number, "Subset simulation",
                             "expected a model run 'level,sample,response,completed' (whole "
                             "numbers, a finite response, completed 0 or 1), got '" +
                               excerpt(line) + "'" + damaged);
          runs.emplace(run->first, run->second);
        }
    }
  } // namespace

  std::vector<std::string>
  subset_journal_files(const std::string &directory)
  {
    std::vector<std::string> names;
    std::error_code          error; // no directory yet: no journal
    for (const auto &entry : std::filesystem::directory_iterator(directory, error))
      if (is_journal(entry.path()))
        names.push_back(entry.path().filename().string());
    return names;
  }

  std::string
  subset_journal_settings(const SubsetSettings &s, const unsigned int n_variables,
                          const double threshold)
  {
    std::string line = "# poundfe subset runs: seed ";
    line += std::to_string(s.seed) + ", samples per level " +
            std::to_string(s.samples_per_level) + ", conditional probability ";
    append_number(line, s.conditional_probability);
    line += ", proposal spread ";
    append_number(line, s.proposal_spread);
    line += ", maximum levels " + std::to_string(s.max_levels) + ", threshold ";
    append_number(line, threshold);
    line += ", random variables " + std::to_string(n_variables);
    // Which chains are longer (N / n_s not whole) decides which sample each
    // recorded response belongs to: a journal of a program that gave the
    // extra states to the first chains is refused, not mixed in.
    line += ", longer chains at random";
    return line;
  }

  SubsetRunsFile::SubsetRunsFile(const std::string &directory, const std::string &settings,
                                 const MPI_Comm comm)
    : directory(directory)
    , settings(settings)
    , comm(comm)
  {
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    if (directory.empty()) // in memory: nothing to resume, nothing written
      {
        AssertThrow(dealii::Utilities::MPI::n_mpi_processes(comm) == 1,
                    dealii::ExcMessage("a Subset Simulation journal in memory is of one rank"));
        return;
      }
    std::string        file, problem, parameter; // of a journal refused on rank 0
    int                line = 0;
    if (rank == 0)
      try
        {
          merge();
        }
      catch (const InputError &e)
        {
          file = e.file(), problem = e.problem(), line = e.line();
          // the entry whose value differs from the journal's record, else
          // the journal's own lines
          parameter = e.parameter().empty() ? "Subset simulation" : e.parameter();
        }
    problem = dealii::Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty()) // every rank throws: none waits for the others
      throw InputError(dealii::Utilities::MPI::broadcast(comm, file, 0),
                       dealii::Utilities::MPI::broadcast(comm, line, 0),
                       dealii::Utilities::MPI::broadcast(comm, parameter, 0), problem);
    // every rank takes the responses the journal holds
    std::vector<double> flat;
    if (rank == 0)
      for (const auto &[key, entry] : earlier)
        flat.insert(flat.end(), {double(key.first), double(key.second), entry.response,
                                 entry.completed ? 1.0 : 0.0});
    flat = dealii::Utilities::MPI::broadcast(comm, flat, 0);
    earlier.clear();
    for (std::size_t i = 0; i + 3 < flat.size(); i += 4)
      earlier[{unsigned(flat[i]), unsigned(flat[i + 1])}] = {flat[i + 2], flat[i + 3] != 0};
    out = std::make_unique<AppendFile>(rank_file(rank));
    out->append(settings + "\n" + columns + "\n");
  }

  SubsetRunsFile::~SubsetRunsFile() = default;

  std::string
  SubsetRunsFile::rank_file(const unsigned int rank) const
  {
    return directory + "/subset_runs.rank" + std::to_string(rank) + ".csv";
  }

  void
  SubsetRunsFile::merge()
  {
    // the record of the model the journal's runs are of (the settings line
    // says only the sampler's settings)
    resume_file(directory + "/" + journal_name);
    std::map<Key, std::pair<double, bool>> runs;
    std::vector<std::filesystem::path>     rank_files;
    if (std::filesystem::is_directory(directory))
      for (const auto &entry : std::filesystem::directory_iterator(directory))
        if (is_journal(entry.path()))
          {
            read_journal(entry.path().string(), settings, runs);
            if (entry.path().filename() != journal_name)
              rank_files.push_back(entry.path());
          }
    earlier.clear();
    for (const auto &[key, run] : runs)
      earlier[key] = {run.first, run.second};
    write_file_atomically(directory + "/" + journal_name, text());
    for (const auto &file : rank_files) // now in subset_runs.csv
      std::filesystem::remove(file);
  }

  bool
  SubsetRunsFile::find(const unsigned int level, const unsigned int sample, double &response) const
  {
    const auto at = earlier.find({level, sample});
    if (at == earlier.end())
      return false;
    response = at->second.response;
    return true;
  }

  void
  SubsetRunsFile::record(const unsigned int level, const unsigned int sample, const double response)
  {
    if (directory.empty())
      {
        kept[{level, sample}] = {response, !last_failed};
        last_failed           = false;
        return;
      }
    Assert(out != nullptr, dealii::ExcMessage("record() after finish()"));
    std::string line = std::to_string(level) + "," + std::to_string(sample) + ",";
    append_number(line, response);
    line += last_failed ? ",0\n" : ",1\n";
    last_failed = false;
    out->append(line);
  }

  unsigned long
  SubsetRunsFile::finish()
  {
    out.reset();
    MPI_Barrier(comm); // every rank's file is complete
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return 0;
    if (directory.empty())
      earlier = std::move(kept);
    else
      merge();
    unsigned long failed = 0;
    for (const auto &[key, entry] : earlier)
      failed += entry.completed ? 0 : 1;
    return failed;
  }

  std::string
  SubsetRunsFile::text() const
  {
    std::string text = settings + "\n" + columns + "\n";
    for (const auto &[key, entry] : earlier)
      {
        text += std::to_string(key.first) + "," + std::to_string(key.second) + ",";
        append_number(text, entry.response);
        text += entry.completed ? ",1\n" : ",0\n";
      }
    return text;
  }
} // namespace poundfe
