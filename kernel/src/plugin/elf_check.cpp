#include "elf_check.hpp"

#include <elf.h>
#include <link.h>  // ElfW: the ELF types of this host's class

#include <bit>
#include <cstring>
#include <fstream>
#include <optional>
#include <system_error>
#include <vector>

namespace sketchlab::plugin_detail {

namespace fs = std::filesystem;

namespace {

using Ehdr = ElfW(Ehdr);
using Phdr = ElfW(Phdr);
using Shdr = ElfW(Shdr);

constexpr unsigned char host_class = sizeof(void*) == 8 ? ELFCLASS64 : ELFCLASS32;
constexpr unsigned char host_data =
    std::endian::native == std::endian::little ? ELFDATA2LSB : ELFDATA2MSB;

bool read_at(std::ifstream& in, std::uint64_t offset, void* out, std::size_t size) {
  in.seekg(static_cast<std::streamoff>(offset));
  in.read(static_cast<char*>(out), static_cast<std::streamsize>(size));
  return static_cast<std::size_t>(in.gcount()) == size;
}

// The machine the running executable was built for (nullopt if unreadable).
std::optional<std::uint16_t> host_machine() {
  static const std::optional<std::uint16_t> machine = []() -> std::optional<std::uint16_t> {
    std::ifstream self("/proc/self/exe", std::ios::binary);
    Ehdr h{};
    if (!self || !read_at(self, 0, &h, sizeof h) || std::memcmp(h.e_ident, ELFMAG, SELFMAG) != 0)
      return std::nullopt;
    return h.e_machine;
  }();
  return machine;
}

std::string segment_type(std::uint32_t type) {
  switch (type) {
    case PT_LOAD: return "LOAD";
    case PT_DYNAMIC: return "DYNAMIC";
    case PT_INTERP: return "INTERP";
    case PT_NOTE: return "NOTE";
    case PT_GNU_EH_FRAME: return "GNU_EH_FRAME";
    default: return "type " + std::to_string(type);
  }
}

// offset + count * size without wrapping around.
std::uint64_t end_of(std::uint64_t offset, std::uint64_t count, std::uint64_t size) {
  if (size != 0 && count > (UINT64_MAX - offset) / size) return UINT64_MAX;
  return offset + count * size;
}

std::string truncated(const std::string& what, std::uint64_t end, std::uint64_t size) {
  return "truncated or damaged: " + what + " needs " + std::to_string(end) +
         " bytes, the file has " + std::to_string(size) + " (an interrupted copy or build?)";
}

}  // namespace

std::string check_elf_library(const fs::path& file) {
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (ec) return "cannot inspect the file: " + ec.message();
  if (fs::is_directory(status)) return "is a directory, not a plugin library";
  // Reading a FIFO or device would block or never end.
  if (!fs::is_regular_file(status)) return "not a regular file";
  const std::uint64_t size = fs::file_size(file, ec);
  if (ec) return "cannot inspect the file: " + ec.message();

  std::ifstream in(file, std::ios::binary);
  if (!in) return std::string("cannot open the file: ") + std::strerror(errno);
  Ehdr h{};
  if (size < sizeof h || !read_at(in, 0, &h, sizeof h) ||
      std::memcmp(h.e_ident, ELFMAG, SELFMAG) != 0)
    return "not an ELF shared library (no ELF header)";
  if (h.e_ident[EI_CLASS] != host_class || h.e_ident[EI_DATA] != host_data)
    return std::string("an ELF file of another class or byte order (") +
           (h.e_ident[EI_CLASS] == ELFCLASS64 ? "64" : "32") + "-bit, " +
           (h.e_ident[EI_DATA] == ELFDATA2LSB ? "little" : "big") + "-endian) than this host";
  if (h.e_type != ET_DYN)
    return "an ELF file but not a shared library (e_type " + std::to_string(h.e_type) + ")";
  if (const auto machine = host_machine(); machine && h.e_machine != *machine)
    return "an ELF shared library for another machine (e_machine " + std::to_string(h.e_machine) +
           ", this host " + std::to_string(*machine) + ")";
  if (h.e_phnum == 0 || h.e_phentsize != sizeof(Phdr))
    return "damaged ELF header: no program headers of the expected size";
  if (const auto end = end_of(h.e_phoff, h.e_phnum, sizeof(Phdr)); end > size)
    return truncated("the program header table", end, size);

  std::vector<Phdr> segments(h.e_phnum);
  if (!read_at(in, h.e_phoff, segments.data(), segments.size() * sizeof(Phdr)))
    return "cannot read the program headers";
  bool loadable = false;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Phdr& p = segments[i];
    loadable = loadable || p.p_type == PT_LOAD;
    if (p.p_filesz == 0) continue;
    if (const auto end = end_of(p.p_offset, 1, p.p_filesz); end > size)
      return truncated("segment " + std::to_string(i) + " (" + segment_type(p.p_type) + ")", end,
                       size);
  }
  if (!loadable) return "damaged ELF file: no loadable segment";
  // The loader never reads the section headers, but they sit at the end of
  // the file: a shorter file has lost its tail.
  if (h.e_shoff != 0) {
    if (h.e_shentsize != sizeof(Shdr)) return "damaged ELF header: unexpected section header size";
    if (const auto end = end_of(h.e_shoff, h.e_shnum, sizeof(Shdr)); end > size)
      return truncated("the section header table", end, size);
  }
  return {};
}

}  // namespace sketchlab::plugin_detail
