// SPDX-License-Identifier: BSD-3-Clause
// HDF5's C API (Debian's libhdf5-dev): datasets of unlimited rows in chunks, rows buffered per
// table and appended a block at a time.

#include "hdf5_tables.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <stdexcept>
#include <system_error>

#include "file_sha256.hpp"

namespace clearjoint::dynamics {

namespace {

/// Rows per chunk and per append: 4096 rows of ~20 doubles are 640 KB, a chunk HDF5 handles well,
/// and the buffer stays small beside the run.
constexpr hsize_t kRowsPerBlock = 4096;

/// zlib level 1: most of the gain of higher levels at a fraction of their time.
constexpr unsigned kDeflateLevel = 1;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error(path.string() + ": " + what + " (HDF5)");
}

/// A handle closed by its HDF5 close function.
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Handle& operator=(Handle&& other) noexcept {
    reset();
    id_ = other.id_;
    close_ = other.close_;
    other.id_ = -1;
    return *this;
  }
  ~Handle() { reset(); }
  void reset() {
    if (id_ >= 0 && close_ != nullptr) close_(id_);
    id_ = -1;
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

void write_text_attribute(hid_t object, const std::string& name, const std::string& text,
                          const std::filesystem::path& path) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid()) fail(path, "cannot create the attribute " + name);
  const char* data = text.c_str();
  if (H5Awrite(attribute.get(), type.get(), &data) < 0) fail(path, "cannot write the attribute " + name);
}

void write_names_attribute(hid_t object, const std::vector<std::string>& names, const std::filesystem::path& path) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  const hsize_t count = names.size();
  Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose);
  Handle attribute(H5Acreate2(object, "columns", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid()) fail(path, "cannot create the attribute columns");
  std::vector<const char*> data;
  for (const std::string& name : names) data.push_back(name.c_str());
  if (H5Awrite(attribute.get(), type.get(), data.data()) < 0) fail(path, "cannot write the attribute columns");
}

}  // namespace

struct Hdf5Tables::Impl {
  struct Table {
    Handle dataset;
    hsize_t columns = 0;
    hsize_t rows_written = 0;
    std::vector<double> buffer;  ///< rows not yet appended, row-major
  };

  std::filesystem::path path;
  std::filesystem::path temporary;
  Handle file;
  Handle group;
  std::vector<Table> tables;
  bool committed = false;

  void append(Table& table) {
    const hsize_t rows = table.buffer.size() / table.columns;
    if (rows == 0) return;
    const hsize_t size[2] = {table.rows_written + rows, table.columns};
    if (H5Dset_extent(table.dataset.get(), size) < 0) fail(path, "cannot extend a table");
    Handle file_space(H5Dget_space(table.dataset.get()), H5Sclose);
    const hsize_t start[2] = {table.rows_written, 0};
    const hsize_t count[2] = {rows, table.columns};
    H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr);
    Handle memory_space(H5Screate_simple(2, count, nullptr), H5Sclose);
    if (H5Dwrite(table.dataset.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(), H5P_DEFAULT,
                 table.buffer.data()) < 0) {
      fail(path, "cannot write rows (the disk may be full)");
    }
    table.rows_written += rows;
    table.buffer.clear();
  }
};

Hdf5Tables::Hdf5Tables(std::filesystem::path path, const std::string& model_json) : impl_(std::make_unique<Impl>()) {
  // HDF5 prints its own error stack on stderr by default; the messages here say what failed.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  impl_->path = std::move(path);
  impl_->temporary = impl_->path;
  impl_->temporary += ".tmp-" + std::to_string(::getpid());
  impl_->file = Handle(H5Fcreate(impl_->temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!impl_->file.valid()) fail(impl_->temporary, "cannot create the file");
  impl_->group = Handle(H5Gcreate2(impl_->file.get(), "tables", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!impl_->group.valid()) fail(impl_->temporary, "cannot create the group tables");
  write_text_attribute(impl_->file.get(), "format", kHdf5RunFormat, impl_->temporary);
  write_text_attribute(impl_->file.get(), "model", model_json, impl_->temporary);
}

Hdf5Tables::~Hdf5Tables() {
  if (impl_->committed) return;
  impl_->tables.clear();
  impl_->group.reset();
  impl_->file.reset();
  std::error_code ignored;
  std::filesystem::remove(impl_->temporary, ignored);
}

std::size_t Hdf5Tables::add_table(const std::string& name, const std::vector<std::string>& header) {
  Impl::Table table;
  table.columns = header.size();
  const hsize_t initial[2] = {0, table.columns};
  const hsize_t maximum[2] = {H5S_UNLIMITED, table.columns};
  Handle space(H5Screate_simple(2, initial, maximum), H5Sclose);
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  const hsize_t chunk[2] = {kRowsPerBlock, table.columns};
  H5Pset_chunk(properties.get(), 2, chunk);
  // Byte shuffle then deflate at its fastest level: time series of doubles whose high bytes
  // repeat shrink to about a third, lossless (h5py and every HDF5 reader undo it).
  H5Pset_shuffle(properties.get());
  H5Pset_deflate(properties.get(), kDeflateLevel);
  table.dataset = Handle(H5Dcreate2(impl_->group.get(), name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                    properties.get(), H5P_DEFAULT),
                         H5Dclose);
  if (!table.dataset.valid()) fail(impl_->temporary, "cannot create the table " + name);
  write_names_attribute(table.dataset.get(), header, impl_->temporary);
  table.buffer.reserve(kRowsPerBlock * table.columns);
  impl_->tables.push_back(std::move(table));
  return impl_->tables.size() - 1;
}

void Hdf5Tables::write_row(std::size_t index, std::span<const double> values) {
  Impl::Table& table = impl_->tables.at(index);
  if (values.size() != table.columns) throw std::logic_error("Hdf5Tables: a row of the wrong width");
  table.buffer.insert(table.buffer.end(), values.begin(), values.end());
  if (table.buffer.size() >= kRowsPerBlock * table.columns) impl_->append(table);
}

void Hdf5Tables::commit() {
  for (Impl::Table& table : impl_->tables) impl_->append(table);
  impl_->tables.clear();
  impl_->group.reset();
  if (H5Fflush(impl_->file.get(), H5F_SCOPE_GLOBAL) < 0) fail(impl_->temporary, "cannot write the file");
  impl_->file.reset();
  std::error_code error;
  std::filesystem::rename(impl_->temporary, impl_->path, error);
  if (error) throw std::runtime_error(impl_->path.string() + ": cannot write the output file (" + error.message() + ")");
  impl_->committed = true;
  write_checksum_file(impl_->path);
}

void Hdf5Tables::add_text_attribute(const std::string& name, const std::string& text) {
  Handle file(H5Fopen(impl_->path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) fail(impl_->path, "cannot reopen the file");
  write_text_attribute(file.get(), name, text, impl_->path);
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) fail(impl_->path, "cannot write the file");
  file.reset();  // closed before its bytes are hashed
  write_checksum_file(impl_->path);
}

}  // namespace clearjoint::dynamics
