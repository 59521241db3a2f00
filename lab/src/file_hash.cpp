#include "sketchlab/lab/file_hash.hpp"

#include <openssl/evp.h>

#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace sketchlab {

FileHash hash_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot open to hash it");
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
    throw std::runtime_error(file.string() + ": cannot start SHA-256");
  FileHash h;
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    if (n > 0 && EVP_DigestUpdate(ctx.get(), buffer.data(), n) != 1)
      throw std::runtime_error(file.string() + ": SHA-256 failed");
    h.bytes += n;
  }
  if (in.bad()) throw std::runtime_error(file.string() + ": read error while hashing");
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(ctx.get(), digest, &length) != 1)
    throw std::runtime_error(file.string() + ": SHA-256 failed");
  static const char hex[] = "0123456789abcdef";
  for (unsigned int i = 0; i < length; ++i) {
    h.sha256 += hex[digest[i] >> 4];
    h.sha256 += hex[digest[i] & 15];
  }
  return h;
}

}  // namespace sketchlab
