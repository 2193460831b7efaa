// SPDX-License-Identifier: BSD-3-Clause
#include "file_sha256.hpp"

#include <openssl/evp.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace clearjoint::dynamics {

namespace {

/// Bytes read per step: large enough that the loop costs nothing beside SHA-256 itself.
constexpr std::size_t kReadBytes = std::size_t{1} << 20;

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw std::runtime_error(file.string() + ": " + what);
}

}  // namespace

std::filesystem::path checksum_path(const std::filesystem::path& file) {
  std::filesystem::path checksum = file;
  checksum += ".sha256";
  return checksum;
}

std::string file_sha256(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, std::string("cannot read the file for its checksum (") + std::strerror(errno) + ")");
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!context || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1) {
    fail(file, "cannot start a SHA-256 (OpenSSL)");
  }
  std::vector<char> buffer(kReadBytes);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const std::streamsize count = in.gcount();
    if (count > 0 && EVP_DigestUpdate(context.get(), buffer.data(), static_cast<std::size_t>(count)) != 1) {
      fail(file, "cannot compute its SHA-256 (OpenSSL)");
    }
  }
  if (in.bad()) fail(file, "cannot read the file for its checksum");
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(context.get(), digest.data(), &length) != 1) fail(file, "cannot compute its SHA-256 (OpenSSL)");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  for (unsigned int k = 0; k < length; ++k) {
    hex += kHex[digest[k] >> 4];
    hex += kHex[digest[k] & 0xF];
  }
  return hex;
}

void write_checksum_file(const std::filesystem::path& file) {
  const std::string line = file_sha256(file) + "  " + file.filename().string() + "\n";
  const std::filesystem::path checksum = checksum_path(file);
  std::filesystem::path temporary = checksum;
  temporary += ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << line;
    out.close();
    if (!out) fail(temporary, std::string("cannot write the checksum file (") + std::strerror(errno) + ")");
  }
  std::error_code error;
  std::filesystem::rename(temporary, checksum, error);
  if (error) {
    const std::string why = error.message();
    std::filesystem::remove(temporary, error);
    fail(checksum, "cannot write the checksum file (" + why + ")");
  }
}

}  // namespace clearjoint::dynamics
