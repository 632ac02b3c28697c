#include <poundfe/base/content_digest.h>
#include <poundfe/commands/rank_agreement.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/base/input_text.h>
#include <poundfe/input/engine_parameters.h>

#include <deal.II/base/mpi.h>

#include <ostream>
#include <sstream>

namespace poundfe
{
  namespace
  {
    std::uint64_t
    digest_of_text(const std::string &text)
    {
      return ContentDigest().add(text).value();
    }

    /// A rank's items as one text, for gathering: the fields of an item
    /// separated by US (0x1f), the items by RS (0x1e).
    std::string
    packed_items(const std::vector<InputItem> &items)
    {
      std::string text;
      for (const InputItem &item : items)
        text += item.name + '\x1f' + std::to_string(item.digest) + '\x1f' + item.unreadable +
                '\x1e';
      return text;
    }

    std::vector<InputItem>
    unpacked_items(const std::string &text)
    {
      std::vector<InputItem> items;
      std::istringstream     in(text);
      for (std::string name, digest, unreadable;
           std::getline(in, name, '\x1f') && std::getline(in, digest, '\x1f') &&
           std::getline(in, unreadable, '\x1e');)
        items.push_back({name, std::stoull(digest), unreadable});
      return items;
    }

    /// Rank 0's message naming the first rank whose items differ from its
    /// own, and the first item in which they do.
    std::string
    difference(const std::vector<std::string> &packed)
    {
      const std::vector<InputItem> root = unpacked_items(packed[0]);
      for (std::size_t rank = 1; rank < packed.size(); ++rank)
        {
          const std::vector<InputItem> other = unpacked_items(packed[rank]);
          for (std::size_t i = 0; i < std::max(root.size(), other.size()); ++i)
            {
              const InputItem *a = i < root.size() ? &root[i] : nullptr;
              const InputItem *b = i < other.size() ? &other[i] : nullptr;
              if (a && b && a->name == b->name && a->digest == b->digest &&
                  a->unreadable == b->unreadable)
                continue;
              const std::string r = "rank " + std::to_string(rank);
              std::string       message = "the ranks were not given the same input: " + r +
                                    "'s differs from rank 0's in " + (a ? a->name : b->name);
              if (b && !b->unreadable.empty())
                message += " (" + r + " cannot read it: " + b->unreadable + ")";
              else if (a && !a->unreadable.empty())
                message += " (rank 0 cannot read it: " + a->unreadable + ")";
              return message;
            }
        }
      return "the ranks were not given the same input"; // a collision of digests only
    }
  } // namespace

  std::vector<InputItem>
  input_items(const std::string &command, const std::string &output,
              const unsigned int n_realizations, const InputParameters &input)
  {
    std::vector<InputItem> items{{"the command", digest_of_text(command), ""},
                                 {"--output", digest_of_text(output), ""},
                                 {"--realizations", n_realizations, ""}};
    for (const auto &[path, value] : input.values)
      items.push_back({"'" + path + "'", digest_of_text(value), ""});
    for (const NamedInputFile &file : named_input_files(input))
      {
        // "(why)" when the file cannot be read: not an error while the
        // ranks agree (a record that modal never reads), named when they don't
        const std::string contents   = input_file_digest(file.path);
        const bool        unreadable = !contents.empty() && contents.front() == '(';
        items.push_back({"the contents of " + file.name + " ('" + file.entry + "')",
                         digest_of_text(contents),
                         unreadable ? contents.substr(1, contents.size() - 2) : ""});
      }
    return items;
  }

  std::optional<int>
  ranks_disagree(const RankInput &mine, const MPI_Comm communicator, std::ostream &err)
  {
    ContentDigest digest;
    for (const InputItem &item : mine.items)
      digest.add(item.name).add(std::to_string(item.digest)).add(item.unreadable);
    // the largest status, and the largest and (as ~) the smallest digest
    std::uint64_t agreed[3] = {std::uint64_t(mine.status), digest.value(), ~digest.value()};
    MPI_Allreduce(MPI_IN_PLACE, agreed, 3, MPI_UINT64_T, MPI_MAX, communicator);
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(communicator);
    if (agreed[0] != 0) // the first message of a rank that could not read its input
      {
        const std::string said =
          mine.status == 0 ? "" :
                             mine.prefix + (rank == 0 ? "" : "rank " + std::to_string(rank) + ": ") +
                               mine.problem + "\n" + mine.trailer;
        const std::vector<std::string> messages =
          dealii::Utilities::MPI::gather(communicator, said, 0);
        for (const std::string &message : messages)
          if (!message.empty())
            {
              err << message;
              break;
            }
        return static_cast<int>(agreed[0]);
      }
    if (agreed[1] == ~agreed[2])
      return std::nullopt;
    const std::vector<std::string> packed =
      dealii::Utilities::MPI::gather(communicator, packed_items(mine.items), 0);
    if (rank == 0)
      err << "poundfe: error: " << difference(packed) << "\n";
    return 1;
  }
} // namespace poundfe
