#include <poundfe/output/atomic_file.h>

#include <filesystem>
#include <stdexcept>

namespace poundfe
{
  AtomicFile::AtomicFile(std::string path)
    : final_path(std::move(path))
    , temporary_path(final_path + ".tmp")
  {
    file = std::fopen(temporary_path.c_str(), "wb");
    if (file == nullptr)
      throw std::runtime_error("cannot write " + temporary_path);
    std::setvbuf(file, nullptr, _IOFBF, 1 << 16);
  }

  AtomicFile::~AtomicFile()
  {
    if (file != nullptr)
      {
        std::fclose(file);
        std::remove(temporary_path.c_str());
      }
  }

  void
  AtomicFile::write(const char *data, const std::size_t size)
  {
    if (std::fwrite(data, 1, size, file) != size)
      throw std::runtime_error("write failed: " + temporary_path);
  }

  void
  AtomicFile::commit()
  {
    if (file == nullptr)
      return;
    const bool ok = std::fflush(file) == 0;
    std::fclose(file);
    file = nullptr;
    if (!ok || std::rename(temporary_path.c_str(), final_path.c_str()) != 0)
      throw std::runtime_error("cannot write " + final_path);
  }

  void
  write_file_atomically(const std::string &path, const std::string &contents)
  {
    AtomicFile file(path);
    file.write(contents);
    file.commit();
  }

  void
  create_directories(const std::string &path)
  {
    std::error_code error;
    std::filesystem::create_directories(path, error);
    if (error)
      throw std::runtime_error("cannot create directory " + path + ": " + error.message());
  }
} // namespace poundfe
