#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/output_directory.h>

#include <algorithm>
#include <cstdio>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <sys/statvfs.h>
#include <unistd.h>

namespace poundfe
{
  namespace
  {
    namespace fs = std::filesystem;

    /// A prepared output directory and its open manifest.
    struct Manifest
    {
      fs::path              directory; // absolute, normal
      int                   descriptor = -1;
      std::set<std::string> listed;
      std::vector<std::string> order; // `listed` in the order they were added
      std::size_t              n_kept = 0; // the first n_kept of `order`: kept from the last run

      ~Manifest()
      {
        if (descriptor >= 0)
          ::close(descriptor);
      }

      /// Appends `entry` unless listed already. One write(2) per line, no
      /// sync: what matters is that a killed process's files are listed,
      /// which the kernel keeps without it.
      void
      add(const std::string &entry)
      {
        if (!listed.insert(entry).second)
          return;
        order.push_back(entry);
        const std::string line = entry + "\n";
        for (std::size_t done = 0; done < line.size();)
          {
            const ssize_t n = ::write(descriptor, line.data() + done, line.size() - done);
            if (n < 0 && errno == EINTR)
              continue;
            if (n < 0)
              throw OutputError("write", (directory / output_manifest_name).string(), errno);
            done += n;
          }
      }
    };

    /// The directories prepared by this process (several in a test).
    std::vector<std::unique_ptr<Manifest>> &
    manifests()
    {
      static std::vector<std::unique_ptr<Manifest>> all;
      return all;
    }

    fs::path
    normal(const std::string &path)
    {
      return fs::absolute(fs::path(path)).lexically_normal();
    }

    /// `path` relative to `directory` when it lies inside it, else empty.
    std::string
    inside(const fs::path &path, const fs::path &directory)
    {
      const fs::path relative = path.lexically_relative(directory);
      if (relative.empty() || relative == "." || *relative.begin() == "..")
        return "";
      std::string text = relative.generic_string();
      while (!text.empty() && text.back() == '/')
        text.pop_back();
      return text;
    }

    /// Whether a manifest line names something poundfe may remove: a
    /// relative path inside the directory (a damaged or edited manifest must
    /// not reach outside it) other than the manifest itself.
    bool
    removable(const std::string &entry)
    {
      const fs::path p(entry);
      if (entry.empty() || p.is_absolute() || entry == output_manifest_name)
        return false;
      for (const fs::path &part : p)
        if (part == ".." || part == "." || part.empty())
          return false;
      return true;
    }

    /// Whether every directory on the way from `root` to `entry`
    /// (removable) is a real directory, not a symbolic link: poundfe creates
    /// no links, so one in the way is the user's, and what lies behind it
    /// (outside the directory, perhaps) is not poundfe's to remove. A link
    /// in the entry's own place is removed as a link (its target stays).
    bool
    reached_without_links(const fs::path &root, const std::string &entry)
    {
      const fs::path  relative(entry);
      fs::path        path = root;
      std::error_code error;
      for (auto part = relative.begin(); part != relative.end() && std::next(part) != relative.end();
           ++part)
        if (path /= *part; !fs::is_directory(fs::symlink_status(path, error)))
          return false;
      return true;
    }

    /// Removes the listed `entry` of `root` (removable, reached without
    /// links) and its "<entry>.tmp". Returns the error of a removal that
    /// failed otherwise than for a missing file.
    std::error_code
    remove_listed(const fs::path &root, const std::string &entry)
    {
      std::error_code failed;
      for (const fs::path &file : {root / entry, root / (entry + ".tmp")})
        if (std::error_code error;
            !fs::remove(file, error) && error && error != std::errc::no_such_file_or_directory)
          failed = error;
      return failed;
    }

    /// Whether `name` is a unique temporary of AtomicFile
    /// (".poundfe-<pid>-<n>.tmp", atomic_file.cc) whose process is gone:
    /// left by a kill -9. A live process's, this one's included, stays.
    bool
    is_stale_temporary(const std::string &name)
    {
      const std::string prefix = ".poundfe-", suffix = ".tmp";
      if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        return false;
      const std::string middle =
        name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
      const std::size_t dash = middle.find('-');
      const auto digits = [](const std::string &t) {
        return !t.empty() && t.size() < 10 &&
               std::all_of(t.begin(), t.end(), [](const char c) { return c >= '0' && c <= '9'; });
      };
      if (dash == std::string::npos || !digits(middle.substr(0, dash)) ||
          !digits(middle.substr(dash + 1)))
        return false;
      const pid_t pid = std::stoi(middle.substr(0, dash));
      return pid > 0 && pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH;
    }

    /// Removes the stale unique temporaries directly in `directory`.
    void
    remove_stale_temporaries(const fs::path &directory)
    {
      std::error_code error;
      for (fs::directory_iterator entry(directory, error), end; !error && entry != end;
           entry.increment(error))
        if (std::error_code failed; is_stale_temporary(entry->path().filename().string()) &&
                                    fs::is_regular_file(entry->symlink_status(failed)))
          fs::remove(entry->path(), failed); // what cannot go stays
    }
  } // namespace

  namespace
  {
    /// expect_output_directory's directory, until it is prepared.
    std::string &
    expected_directory()
    {
      static std::string directory;
      return directory;
    }

    using ResumeInputs = std::vector<std::pair<std::string, std::string>>;

    /// The inputs of the command under way (expect_output_directory).
    ResumeInputs &
    command_resume_inputs()
    {
      static ResumeInputs inputs;
      return inputs;
    }

    constexpr const char *resume_record_suffix = ".inputs";

    /// The input files named by the input of the command under way.
    std::vector<NamedInputFile> &
    command_input_files()
    {
      static std::vector<NamedInputFile> files;
      return files;
    }

    /// A record line's path that holds a file's digest begins so.
    constexpr const char *digest_prefix = "digest of the ";

    /// The digest lines of the files named now: ("digest of the record
    /// file 'x.at2' (Ground motion/Record/File)", "1234 bytes, FNV-1a ...").
    ResumeInputs
    current_digests()
    {
      ResumeInputs digests;
      for (const NamedInputFile &f : command_input_files())
        digests.emplace_back(digest_prefix + f.what + " '" + f.name + "' (" + f.entry + ")",
                             input_file_digest(f.path));
      return digests;
    }

    /// The text of a file poundfe wrote into an output directory, read as
    /// any input (read_input_text: a FIFO, a device or a huge file put in
    /// its place is refused, not read forever); "" when it does not exist.
    std::string
    own_file_text(const fs::path &file, const std::string &what)
    {
      std::error_code error;
      if (!fs::exists(fs::symlink_status(file, error)))
        return "";
      return read_input_text(file.string(), what);
    }
  } // namespace

  namespace
  {
    /// The manifest the last command left in `root`; "" when there is none,
    /// or a link in its place (no manifest of poundfe's).
    std::string
    earlier_manifest_text(const fs::path &root)
    {
      const fs::path  listing = root / output_manifest_name;
      std::error_code error;
      return fs::is_symlink(fs::symlink_status(listing, error)) ?
               std::string() :
               own_file_text(listing, "output manifest");
    }

    /// A new, empty manifest in `root`, opened to append: a link in its
    /// place goes first, not the file it points to (which opening it would
    /// truncate). Throws OutputError.
    int
    open_new_manifest(const fs::path &root)
    {
      const std::string name = (root / output_manifest_name).string();
      if (std::error_code error; fs::is_symlink(fs::symlink_status(name, error)))
        fs::remove(name, error);
      const int descriptor =
        ::open(name.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC | O_NOFOLLOW, 0666);
      if (descriptor < 0) // the first file written here: say it of the directory
        throw OutputError("write in the output directory", root.string(), errno);
      return descriptor;
    }
  } // namespace

  void
  prepare_output_directory(const std::string &directory, const std::vector<std::string> &resumed)
  {
    // prepared now, by the command itself (with what it resumes): not again
    // at its first file (its own create_directories below included)
    if (!expected_directory().empty() && normal(expected_directory()) == normal(directory))
      expected_directory().clear();
    create_directories(directory);
    const fs::path root = normal(directory);
    auto          &all  = manifests();
    all.erase(std::remove_if(all.begin(), all.end(),
                             [&](const auto &m) { return m->directory == root; }),
              all.end());

    // What the last command listed: files now, then the subdirectories
    // that are left empty, deepest first.
    std::vector<std::string> kept, directories;
    std::istringstream       old(earlier_manifest_text(root));
    for (std::string entry; std::getline(old, entry);)
      {
        if (!removable(entry) || !reached_without_links(root, entry))
          continue;
        const fs::path  path = root / entry;
        std::error_code error;
        if (fs::is_directory(fs::symlink_status(path, error)))
          {
            directories.push_back(entry);
            continue;
          }
        const std::string name = path.filename().string();
        const auto        is_resumed = [&](const std::string &r) {
          return name == r || name == r + resume_record_suffix;
        };
        if (std::any_of(resumed.begin(), resumed.end(), is_resumed))
          {
            if (fs::exists(fs::symlink_status(path, error)))
              kept.push_back(entry);
            continue;
          }
        if (const std::error_code failed = remove_listed(root, entry))
          throw OutputError("remove the earlier run's file", path.string(), failed.value());
      }
    // a long name's unique temporary (atomic_file.cc) left by a kill -9:
    // in the directory or one it listed, reached without links
    remove_stale_temporaries(root);
    for (const std::string &entry : directories)
      remove_stale_temporaries(root / entry);
    std::sort(directories.begin(), directories.end(),
              [](const std::string &a, const std::string &b) { return a.size() > b.size(); });
    for (const std::string &entry : directories)
      {
        std::error_code error; // not empty: the user's files, or resumed ones
        if (!fs::remove(root / entry, error))
          kept.push_back(entry);
      }

    auto manifest       = std::make_unique<Manifest>();
    manifest->directory = root;
    manifest->descriptor = open_new_manifest(root);
    // parents before what they hold, so a later removal empties them first
    std::sort(kept.begin(), kept.end());
    for (const std::string &entry : kept)
      manifest->add(entry);
    manifest->n_kept = manifest->order.size();
    all.push_back(std::move(manifest));
  }

  void
  discard_output_directory(const std::string &directory)
  {
    const fs::path root  = normal(directory);
    auto          &all   = manifests();
    const auto     found = std::find_if(all.begin(), all.end(),
                                    [&](const auto &m) { return m->directory == root; });
    if (found == all.end() || (*found)->n_kept > 0) // nothing written, or a resumed table
      return;
    std::vector<std::string> entries = (*found)->order;
    all.erase(found); // closes the manifest
    // files first, then the directories, deepest first (parents are listed
    // before what they hold)
    std::reverse(entries.begin(), entries.end());
    for (const std::string &entry : entries) // what cannot go stays: never worse than before
      if (removable(entry) && reached_without_links(root, entry))
        remove_listed(root, entry);
    std::error_code error;
    fs::remove(root / output_manifest_name, error);
    fs::remove(root, error); // only when empty: the user's own files stay
  }

  void
  expect_output_directory(const std::string &directory, ResumeInputs resume_inputs,
                          std::vector<NamedInputFile> input_files)
  {
    expected_directory()    = directory;
    command_resume_inputs() = std::move(resume_inputs);
    command_input_files()   = std::move(input_files);
  }

  namespace
  {
    /// The "path = value" lines of a resume record. A digest line splits at
    /// its last " = " (a file name may hold one, a digest never), the
    /// others at their first (an entry's name never holds one).
    std::map<std::string, std::string>
    read_resume_record(const std::string &record)
    {
      std::map<std::string, std::string> lines;
      std::istringstream                 in(own_file_text(record, "record of the input"));
      for (std::string line; std::getline(in, line);)
        if (const std::size_t at = line.rfind(digest_prefix, 0) == 0 ? line.rfind(" = ") :
                                                                       line.find(" = ");
            at != std::string::npos)
          lines.emplace(line.substr(0, at), line.substr(at + 3));
      return lines;
    }

    /// Refuses `file` unless every file the input names now has the
    /// digest it had when the record `before` was written.
    void
    compare_digests(const std::string &file, const std::map<std::string, std::string> &before)
    {
      const std::string remedy = "; remove " + fs::path(file).filename().string() +
                                 " (its realizations are computed again) or choose another "
                                 "output directory";
      const bool any_before =
        std::any_of(before.begin(), before.end(),
                    [](const auto &line) { return line.first.rfind(digest_prefix, 0) == 0; });
      for (const auto &[path, digest] : current_digests())
        {
          const std::string named = path.substr(std::strlen("digest of ")); // "the ... (entry)"
          const auto        then  = before.find(path);
          if (!any_before)
            throw InputError(file, 0, "",
                             "holds realizations whose record of the input has no digest of the "
                             "files the input names (written by an earlier version of poundfe), "
                             "so whether " + named + " changed since cannot be checked" + remedy);
          if (then == before.end())
            throw InputError(file, 0, "",
                             "holds realizations computed without " + named + remedy);
          if (then->second != digest)
            throw InputError(file, 0, "",
                             named + " changed since these realizations were computed (then " +
                               then->second + ", now " + digest + ")" + remedy);
        }
    }
  } // namespace

  void
  resume_file(const std::string &file)
  {
    const ResumeInputs &now = command_resume_inputs();
    if (now.empty())
      return;
    const std::string record = file + resume_record_suffix;
    std::error_code   error;
    if (!fs::exists(fs::symlink_status(file, error)))
      {
        std::string text;
        for (const ResumeInputs &lines : {now, current_digests()})
          for (const auto &[path, value] : lines)
            text += path + " = " + value + "\n";
        write_file_atomically(record, text);
        return;
      }
    const std::string remedy = "; remove it (its realizations are computed again) or choose another "
                               "output directory";
    if (!fs::exists(fs::symlink_status(record, error)))
      throw InputError(file, 0, "",
                       "holds realizations of an earlier run that left no record of its input (" +
                         fs::path(record).filename().string() + "), so they may belong to another model" +
                         remedy);
    std::map<std::string, std::string> before = read_resume_record(record);
    const auto value_before = [&](const std::string &path) {
      const auto it = before.find(path);
      return it == before.end() ? std::string("(no such entry then)") : it->second;
    };
    if (const std::string command = value_before("command"); command != now.front().second)
      throw InputError(file, 0, "",
                       "holds the realizations of `" + command + "`, not of `" + now.front().second +
                         "`" + remedy);
    std::map<std::string, std::string> current(now.begin(), now.end());
    for (const auto &[path, value] : before) // an entry this version no longer has
      if (path.rfind(digest_prefix, 0) != 0)   // (a file no longer named: its entry changed)
        current.emplace(path, "(no such entry now)");
    for (const auto &[path, value] : current)
      if (value_before(path) != value)
        throw InputError(file, 0, path,
                         "holds realizations computed with '" + value_before(path) +
                           "'; the input now gives '" + value +
                           "', and one table must not mix two models" + remedy);
    compare_digests(file, before);
  }

  void
  register_output(const std::string &path)
  {
    if (const std::string expected = expected_directory(); !expected.empty())
      {
        const fs::path root = normal(expected), p = normal(path);
        if (p == root || !inside(p, root).empty())
          {
            expected_directory().clear(); // before: preparing creates the directory
            if (!output_directory_prepared(expected))
              prepare_output_directory(expected);
          }
      }
    auto &all = manifests();
    if (all.empty())
      return;
    const fs::path p = normal(path);
    // the innermost prepared directory that holds it
    Manifest   *owner = nullptr;
    std::string entry;
    for (const auto &manifest : all)
      if (std::string relative = inside(p, manifest->directory);
          !relative.empty() && (!owner || relative.size() < entry.size()))
        owner = manifest.get(), entry = std::move(relative);
    if (!owner)
      return;
    // its parents first ("solution" before "solution/solution-00000.vtu"),
    // so that they are removed once empty
    for (std::size_t slash = entry.find('/'); slash != std::string::npos;
         slash = entry.find('/', slash + 1))
      owner->add(entry.substr(0, slash));
    owner->add(entry);
  }

  namespace
  {
    /// The manifest of the prepared `directory`, nullptr if none.
    Manifest *
    manifest_of(const std::string &directory)
    {
      const fs::path root = normal(directory);
      for (const auto &manifest : manifests())
        if (manifest->directory == root)
          return manifest.get();
      return nullptr;
    }
  } // namespace

  bool
  output_directory_prepared(const std::string &directory)
  {
    return manifest_of(directory) != nullptr;
  }

  std::vector<std::string>
  remove_temporaries(const std::string &directory)
  {
    std::vector<std::string> present;
    const Manifest *manifest = manifest_of(directory);
    if (!manifest)
      return present;
    for (const std::string &entry : manifest->order)
      {
        if (!reached_without_links(manifest->directory, entry))
          continue; // a link in the way: the user's, not poundfe's file
        const fs::path  path = manifest->directory / entry;
        std::error_code error;
        fs::remove(fs::path(path.string() + ".tmp"), error); // gone already: fine
        if (fs::is_regular_file(fs::symlink_status(path, error)))
          present.push_back(entry);
      }
    return present;
  }

  double
  csv_table_bytes(const double rows, const double columns)
  {
    return rows * columns * 20;
  }

  void
  require_free_space(const std::string &directory, const double bytes, const std::string &what)
  {
    fs::path        existing = normal(directory);
    std::error_code error;
    while (!fs::exists(existing, error) && existing.has_parent_path() && existing != existing.parent_path())
      existing = existing.parent_path();
    struct statvfs disk;
    if (::statvfs(existing.c_str(), &disk) != 0)
      return; // no answer (a network file system): the writes will tell
    const double free = double(disk.f_bavail) * double(disk.f_frsize);
    if (bytes <= free)
      return;
    const auto gigabytes = [](const double b) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g GB", b / 1e9);
      return std::string(text);
    };
    // refused before a byte is written: said as the full disk it would end in
    throw OutputError("write the " + what + " (about " + gigabytes(bytes) + "; " + gigabytes(free) +
                        " free) in",
                      existing.string(), ENOSPC);
  }
} // namespace poundfe
