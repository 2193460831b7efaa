// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The SHA-256 of a file, and the checksum file beside it in sha256sum's format
/// (`<hex>  <name>`, so that `sha256sum -c run.h5.sha256` checks it). A run's HDF5 file carries
/// one (hdf5_tables.hpp): libhdf5 trusts its input, so a reader checks the bytes first
/// (clearjoint.read_run refuses a file that does not match).

#include <filesystem>
#include <string>

namespace clearjoint::dynamics {

/// The checksum file of `file`: its name with ".sha256" appended.
std::filesystem::path checksum_path(const std::filesystem::path& file);

/// SHA-256 of the bytes of `file`, as 64 lowercase hexadecimal digits (OpenSSL's libcrypto).
/// std::runtime_error naming the file when it cannot be read.
std::string file_sha256(const std::filesystem::path& file);

/// Writes checksum_path(file) for the bytes `file` holds now, under a temporary name first and
/// then renamed, so that the checksum file is whole or absent. std::runtime_error naming it.
void write_checksum_file(const std::filesystem::path& file);

}  // namespace clearjoint::dynamics
