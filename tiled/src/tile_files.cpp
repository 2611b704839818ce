#include "tile_files.h"

#include "vrs/tiled.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

namespace vrs::tiled {

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error(what + ": " + std::strerror(errno));
}

} // namespace

std::string unfinished_name(const std::string& path, long pid) {
  return path + ".tmp." + std::to_string(pid);
}

RecordWriter::RecordWriter(std::string path, bool durable)
    : path_(std::move(path)), tmp_(unfinished_name(path_, getpid())), durable_(durable) {
  f_ = std::fopen(tmp_.c_str(), "wb");
  if (!f_) fail("cannot write " + tmp_);
  std::setvbuf(f_, nullptr, _IOFBF, 1 << 16);
}

RecordWriter::~RecordWriter() {
  if (f_) {
    std::fclose(f_);
    std::remove(tmp_.c_str());
  }
}

void RecordWriter::write(const void* data, size_t bytes) {
  // Unlocked: a writer is one thread's, and the lock was a tenth of the streaming pass.
  if (fwrite_unlocked(data, 1, bytes, f_) != bytes) fail("cannot write " + tmp_);
}

void RecordWriter::commit() {
  std::FILE* f = f_;
  f_ = nullptr;
  if (std::fflush(f) != 0 || (durable_ && fsync(fileno(f)) != 0)) {
    std::fclose(f);
    std::remove(tmp_.c_str());
    fail("cannot write " + tmp_);
  }
  std::fclose(f);
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    std::remove(tmp_.c_str());
    fail("cannot rename " + tmp_);
  }
}

void for_each_record(const std::string& path, bool keys,
                     const std::function<void(const FaceRecord&)>& fn) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) fail("cannot read " + path);
  const size_t size = record_size(keys);
  std::vector<unsigned char> buf(4096 * size);
  FaceRecord r{};
  size_t n;
  while ((n = std::fread(buf.data(), size, 4096, f)) > 0)
    for (size_t i = 0; i < n; ++i) {
      std::memcpy(&r, &buf[i * size], size);
      fn(r);
    }
  const bool bad = std::ferror(f);
  std::fclose(f);
  if (bad) fail("cannot read " + path);
}

uint64_t record_count(const std::string& path, bool keys) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) fail("missing " + path);
  return uint64_t(st.st_size) / record_size(keys);
}

State read_state(const std::string& dir) {
  State s;
  std::FILE* f = std::fopen((dir + "/state").c_str(), "r");
  if (!f) fail("not a tiled run's work directory (no state): " + dir);
  char key[256], value[4096];
  while (std::fscanf(f, "%255s %4095[^\n]", key, value) == 2)
    s[key] = value;
  std::fclose(f);
  return s;
}

void write_state(const std::string& dir, const State& s) {
  RecordWriter w(dir + "/state");
  for (const auto& [k, v] : s) {
    const std::string line = k + " " + v + "\n";
    w.write(line.data(), line.size());
  }
  w.commit();
}

double state_number(const State& s, const std::string& key) {
  auto it = s.find(key);
  if (it == s.end()) throw std::runtime_error("work directory state lacks " + key);
  return std::strtod(it->second.c_str(), nullptr);
}

std::string tile_path(const std::string& dir, int level, size_t tile, const char* ext) {
  return dir + "/L" + std::to_string(level) + "/" + std::to_string(tile) + ext;
}

void make_dir(const std::string& path) {
  if (mkdir(path.c_str(), 0755) != 0 && errno != EEXIST) fail("cannot make " + path);
  if (access(path.c_str(), W_OK) != 0) fail("cannot write in " + path);
}

void remove_tree(const std::string& path) {
  if (DIR* d = opendir(path.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name == "." || name == "..") continue;
      const std::string child = path + "/" + name;
      struct stat st;
      if (lstat(child.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        remove_tree(child);
      else
        std::remove(child.c_str());
    }
    closedir(d);
  }
  rmdir(path.c_str());
}

} // namespace vrs::tiled
