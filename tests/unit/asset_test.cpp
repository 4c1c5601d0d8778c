// The ASSET file store: names, the file format, the sandbox, and writes that a kill
// cannot tear.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <set>

#include "devices/asset_channels.h"
#include "devices/asset_store.h"

namespace ncc::asset {
namespace {

namespace fs = std::filesystem;

const Layout kOrigins = {{FieldType::Integer, 2},
                         {FieldType::Chars, 1},
                         {FieldType::LongReal, 8},
                         {FieldType::Chars, 3},
                         {FieldType::Real, 4}};

// A sandbox of its own for each test, with the devices given, removed afterwards.
class Sandbox {
 public:
  explicit Sandbox(std::initializer_list<int> devices = {1, 3}) {
    std::string pattern = (fs::temp_directory_path() / "ncc-asset-XXXXXX").string();
    dir_ = ::mkdtemp(pattern.data());
    for (int d : devices) fs::create_directory(dir_ / ("MP" + std::to_string(d)));
  }
  ~Sandbox() { fs::remove_all(dir_); }
  const fs::path& dir() const { return dir_; }
  std::unique_ptr<Store> store(Store::Options options = {}) const {
    std::string why;
    auto s = Store::open(dir_.string(), options, why);
    EXPECT_TRUE(s) << why;
    return s;
  }

 private:
  fs::path dir_;
};

FileName name(std::string_view text) { return *parse_file_name(text, 1); }

TEST(AssetNames, WhatAFileMayBeCalled) {
  EXPECT_EQ(parse_file_name("FILQ/MP3", 1), (FileName{"FILQ", 3}));
  EXPECT_EQ(parse_file_name("ORIG", 1), (FileName{"ORIG", 1}));
  EXPECT_EQ(parse_file_name("A12345/MP0", 1), (FileName{"A12345", 0}));
  EXPECT_EQ(parse_file_name("PUNTXZ/MP6", 1)->text(), "PUNTXZ/MP6");
  for (std::string_view bad : {"", "filq", "TOOLONG", "9A", "../X", "A/B", "/ETC", "X/MP7", "X/MP", "X/MP33", "A.B",
                               "..", "A B", "X/", "X/mp3"})
    EXPECT_FALSE(parse_file_name(bad, 1)) << bad;
}

TEST(AssetFields, FormatsAndTheirBytes) {
  EXPECT_EQ(parse_field("IN"), (Field{FieldType::Integer, 2}));
  EXPECT_EQ(parse_field("RE"), (Field{FieldType::Real, 4}));
  EXPECT_EQ(parse_field("LR"), (Field{FieldType::LongReal, 8}));
  EXPECT_EQ(parse_field("CH"), (Field{FieldType::Chars, 1}));
  EXPECT_EQ(parse_field("32CH"), (Field{FieldType::Chars, 32}));
  for (std::string_view bad : {"0CH", "33CH", "BY", "BL", "LI", "-1CH", "3 CH", ""})
    EXPECT_FALSE(parse_field(bad)) << bad;
  for (const Field& f : kOrigins) EXPECT_EQ(parse_field(field_text(f)), f);
  EXPECT_EQ(record_length(kOrigins), 18u);
  EXPECT_TRUE(well_formed(kOrigins));
  EXPECT_FALSE(well_formed({}));
  EXPECT_FALSE(well_formed(Layout(18, Field{})));
  EXPECT_TRUE(well_formed(Layout(17, Field{})));
  EXPECT_FALSE(well_formed({{FieldType::Real, 8}}));
}

TEST(AssetFile, BlankRecordsAreZeroAndBlanks) {
  File f = blank_file({{FieldType::Integer, 2}, {FieldType::Chars, 3}}, 2);
  EXPECT_EQ(f.data, std::string("\0\0   \0\0   ", 10));
}

TEST(AssetFile, FieldsHoldWhatTheirFormatCan) {
  File f = blank_file(kOrigins, 2);
  EXPECT_TRUE(set_number(f, 2, 0, -32768));
  EXPECT_TRUE(set_chars(f, 2, 1, "X"));
  EXPECT_TRUE(set_number(f, 2, 2, 0.1));
  EXPECT_TRUE(set_chars(f, 2, 3, "AB"));
  EXPECT_TRUE(set_number(f, 2, 4, 0.1));
  EXPECT_EQ(number(f, 2, 0), -32768);
  EXPECT_EQ(chars(f, 2, 1), "X");
  EXPECT_EQ(number(f, 2, 2), 0.1);
  EXPECT_EQ(chars(f, 2, 3), "AB ");
  EXPECT_EQ(number(f, 2, 4), static_cast<double>(0.1f));
  EXPECT_EQ(number(f, 1, 0), 0);  // record 1 untouched
  EXPECT_EQ(chars(f, 1, 3), "   ");
  // Record 2 field 1 is the bytes after record 1 (18 bytes) : 0x8000 little-endian.
  EXPECT_EQ(f.data.substr(18, 2), std::string("\0\x80", 2));
  for (double bad : {32768.0, -32769.0, 0.5, std::nan("")}) EXPECT_FALSE(set_number(f, 1, 0, bad)) << bad;
  EXPECT_FALSE(set_number(f, 1, 4, 1e39));
  EXPECT_FALSE(set_number(f, 1, 4, double{std::numeric_limits<float>::max()} + 0x1p103));
  EXPECT_TRUE(set_number(f, 1, 4, -3.4028235e38));  // FLT_MAX as printed: rounds to it
  EXPECT_EQ(number(f, 1, 4), -double{std::numeric_limits<float>::max()});
  EXPECT_TRUE(set_number(f, 1, 4, 0));
  EXPECT_FALSE(set_number(f, 1, 2, std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(set_number(f, 1, 1, 1));
  EXPECT_FALSE(set_chars(f, 1, 1, "XY"));
  EXPECT_FALSE(set_chars(f, 1, 0, "X"));
  EXPECT_EQ(f.data.substr(0, 18), blank_file(kOrigins, 1).data);  // failed sets change nothing
}

TEST(AssetFile, RoundTripsAndItsBytesAreFixed) {
  File f = blank_file(kOrigins, 3);
  f.write_protected = true;
  f.data[0] = 7;
  File back;
  ASSERT_EQ(decode(encode(f), back), Code::Ok);
  EXPECT_EQ(back, f);
  // docs/asset.md: the header, little-endian.
  const std::string bytes = encode(blank_file({{FieldType::Chars, 2}}, 1));
  EXPECT_EQ(bytes.substr(0, 16), std::string("NCAF\1\0\0\0\1\0\2\0\1\0\0\0", 16));
  EXPECT_EQ(bytes.size(), 24u + 2 + 2);
  EXPECT_EQ(bytes.substr(24), std::string("\4\2  ", 4));
}

TEST(AssetFile, AnyDamageIsALogicalError) {
  const std::string good = encode(blank_file(kOrigins, 2));
  File f;
  for (size_t i = 0; i < good.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::string bad = good;
      bad[i] = static_cast<char>(bad[i] ^ (1 << bit));
      EXPECT_EQ(decode(bad, f), Code::Logical) << "byte " << i << " bit " << bit;
    }
  for (size_t n = 0; n < good.size(); ++n) EXPECT_EQ(decode(good.substr(0, n), f), Code::Logical) << n;
  EXPECT_EQ(decode(good + '\0', f), Code::Logical);
}

TEST(AssetStore, CreateLoadReplaceRemove) {
  Sandbox box;
  auto store = box.store();
  File f = blank_file(kOrigins, 4);
  EXPECT_EQ(store->create(name("ORIG/MP3"), f), Code::Ok);
  EXPECT_EQ(store->create(name("ORIG/MP3"), f), Code::Exists);
  File got;
  EXPECT_EQ(store->load(name("ORIG/MP3"), got), Code::Ok);
  EXPECT_EQ(got, f);
  f.data[3] = 'X';
  EXPECT_EQ(store->replace(name("ORIG/MP3"), f), Code::Ok);
  EXPECT_EQ(store->load(name("ORIG/MP3"), got), Code::Ok);
  EXPECT_EQ(got, f);
  EXPECT_EQ(store->replace(name("OTHER/MP3"), f), Code::NotFound);
  EXPECT_EQ(store->load(name("OTHER/MP3"), got), Code::NotFound);
  EXPECT_EQ(store->create(name("B/MP3"), f), Code::Ok);
  EXPECT_EQ(store->list(3), (std::vector<FileName>{name("B/MP3"), name("ORIG/MP3")}));
  EXPECT_EQ(store->remove(name("ORIG/MP3")), Code::Ok);
  EXPECT_EQ(store->remove(name("ORIG/MP3")), Code::NotFound);
  EXPECT_EQ(store->list(3), (std::vector<FileName>{name("B/MP3")}));
  // Nothing but the files is left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(box.dir() / "MP3"), fs::directory_iterator()), 1);
}

TEST(AssetStore, DevicesAndNamesStayInTheSandbox) {
  Sandbox box({1, 3});
  fs::create_directory(box.dir() / "outside");
  fs::create_directory_symlink(box.dir() / "outside", box.dir() / "MP2");  // a linked device is not connected
  auto store = box.store();
  File f = blank_file(kOrigins, 1);
  File got;
  EXPECT_EQ(store->create(name("X/MP4"), f), Code::BadDevice);
  EXPECT_EQ(store->load(name("X/MP4"), got), Code::BadDevice);
  EXPECT_EQ(store->create(name("X/MP2"), f), Code::BadDevice);
  EXPECT_TRUE(fs::is_empty(box.dir() / "outside"));
  // A name the parser would refuse is refused here too (a hostile bytecode file).
  EXPECT_EQ(store->create(FileName{"../X", 1}, f), Code::Illegal);
  EXPECT_EQ(store->load(FileName{"../MP3/X", 1}, got), Code::NotFound);
  EXPECT_EQ(store->remove(FileName{"..", 1}), Code::NotFound);
  // A file that is a link, or not a file, is not an ASSET file.
  ASSERT_EQ(store->create(name("REAL/MP1"), f), Code::Ok);
  fs::create_symlink(box.dir() / "MP1" / "REAL.nca", box.dir() / "MP1" / "LINK.nca");
  fs::create_directory(box.dir() / "MP1" / "DIR.nca");
  EXPECT_EQ(store->load(name("LINK/MP1"), got), Code::Logical);
  EXPECT_EQ(store->replace(name("LINK/MP1"), f), Code::Logical);
  EXPECT_EQ(store->remove(name("LINK/MP1")), Code::Logical);
  EXPECT_EQ(store->load(name("DIR/MP1"), got), Code::Logical);
  ASSERT_EQ(::mkfifo((box.dir() / "MP1" / "PIPE.nca").c_str(), 0644), 0);
  EXPECT_EQ(store->load(name("PIPE/MP1"), got), Code::Logical);  // and it does not hang
  EXPECT_TRUE(fs::is_symlink(box.dir() / "MP1" / "LINK.nca"));
  // A damaged file reads as one.
  std::FILE* out = std::fopen((box.dir() / "MP1" / "BAD.nca").c_str(), "wb");
  std::fputs("NCAF", out);
  std::fclose(out);
  EXPECT_EQ(store->load(name("BAD/MP1"), got), Code::Logical);
}

TEST(AssetStore, ADeviceHoldsWhatItHasRoomFor) {
  Sandbox box;
  auto store = box.store({.device_bytes = 2 * (24 + 2 + 100)});
  const Layout chars = {{FieldType::Chars, 10}};
  EXPECT_EQ(store->create(name("A/MP1"), blank_file(chars, 10)), Code::Ok);
  EXPECT_EQ(store->create(name("B/MP1"), blank_file(chars, 10)), Code::Ok);
  EXPECT_EQ(store->create(name("C/MP1"), blank_file(chars, 1)), Code::Overflow);
  EXPECT_EQ(store->replace(name("B/MP1"), blank_file(chars, 10)), Code::Ok);  // the same size again
  EXPECT_EQ(store->replace(name("B/MP1"), blank_file(chars, 11)), Code::Overflow);
  EXPECT_EQ(store->create(name("C/MP3"), blank_file(chars, 10)), Code::Ok);  // another device
}

// A writer killed at any moment leaves the file whole: the version before a write or
// the one after it, never a mix.
TEST(AssetStore, AKilledWriterNeverTearsAFile) {
  Sandbox box;
  const Layout layout = {{FieldType::LongReal, 8}, {FieldType::Chars, 32}};
  auto version = [&](uint32_t v) {
    File f = blank_file(layout, 200);
    for (size_t i = 0; i < f.data.size(); ++i) f.data[i] = static_cast<char>('A' + v % 26);
    return f;
  };
  ASSERT_EQ(box.store()->create(name("LOG/MP1"), version(0)), Code::Ok);
  std::mt19937 random(6);
  std::set<char> seen;  // the versions found: the writers got on
  for (int round = 0; round < 20; ++round) {
    // The writer says each version it has written, so that it is killed after some
    // whatever the machine's load, and at a random moment of the next.
    int done[2];
    ASSERT_EQ(::pipe(done), 0);
    pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::close(done[0]);
      auto store = box.store();
      for (uint32_t v = 1;; ++v) {
        if (store->replace(name("LOG/MP1"), version(v)) != Code::Ok) ::_exit(1);
        if (::write(done[1], "v", 1) != 1) ::_exit(1);
      }
    }
    ::close(done[1]);
    char written = 0;
    for (unsigned n = 1 + random() % 3; n > 0; --n) ASSERT_EQ(::read(done[0], &written, 1), 1);
    ::usleep(random() % 5000);
    ::kill(child, SIGKILL);
    ::close(done[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the writer stopped by itself";
    File got;
    ASSERT_EQ(box.store()->load(name("LOG/MP1"), got), Code::Ok) << "round " << round;
    EXPECT_EQ(got.data, std::string(got.data.size(), got.data[0])) << "round " << round;
    seen.insert(got.data[0]);
    EXPECT_EQ(box.store()->list(1), (std::vector<FileName>{name("LOG/MP1")}));
  }
  EXPECT_GT(seen.size(), 1u);
}

// ---- The statements of a process ------------------------------------------------------

class AssetChannels : public ::testing::Test {
 protected:
  AssetChannels() : store(box.store()) {
    File f = blank_file(kOrigins, 3);
    EXPECT_TRUE(set_number(f, 3, 0, 2));
    EXPECT_TRUE(set_chars(f, 3, 1, "Z"));
    EXPECT_TRUE(set_number(f, 3, 2, -12.5));
    EXPECT_EQ(store->create(name("ORIG/MP3"), f), Code::Ok);
    File locked = blank_file(kOrigins, 1);
    locked.write_protected = true;
    EXPECT_EQ(store->create(name("LOCKED/MP3"), locked), Code::Ok);
  }
  Sandbox box;
  std::unique_ptr<Store> store;
  OpenFiles open_files;
};

TEST_F(AssetChannels, WithoutASandboxEveryStatementIsCode18) {
  Channels none(nullptr, open_files, {});
  std::vector<Value> v;
  EXPECT_EQ(none.open(1, name("ORIG/MP3"), false), Code::NotConfigured);
  EXPECT_EQ(none.read(1, 1, 1, v), Code::NotConfigured);
  EXPECT_EQ(none.write(1, 1, 1, v), Code::NotConfigured);
  EXPECT_EQ(none.close(1), Code::NotConfigured);
  EXPECT_EQ(none.close_all(), Code::NotConfigured);
  EXPECT_EQ(none.create(1, name("X"), 1), Code::NotConfigured);
  EXPECT_EQ(none.remove(name("ORIG/MP3")), Code::NotConfigured);
}

TEST_F(AssetChannels, OpenAndItsErrorsInOrder) {
  Channels p(store.get(), open_files, {.channels = 8});
  EXPECT_EQ(p.open(0, name("ORIG/MP3"), false), Code::BadChannel);
  EXPECT_EQ(p.open(9, name("ORIG/MP3"), false), Code::BadChannel);
  EXPECT_EQ(p.open(1, name("NONE/MP3"), false), Code::NotFound);
  EXPECT_EQ(p.open(1, name("ORIG/MP5"), false), Code::BadDevice);
  EXPECT_EQ(p.open(1, name("LOCKED/MP3"), true), Code::Protected);
  EXPECT_EQ(p.open(1, name("LOCKED/MP3"), false), Code::Ok);
  EXPECT_EQ(p.open(1, name("ORIG/MP3"), false), Code::ChannelState);  // occupied, before anything about the file
  EXPECT_EQ(p.open(1, name("NONE/MP3"), false), Code::ChannelState);
  EXPECT_EQ(p.open(2, name("ORIG/MP3"), true), Code::Ok);
  // Another process: a file open for writing is open nowhere else; reading is shared.
  Channels q(store.get(), open_files, {});
  EXPECT_EQ(q.open(1, name("ORIG/MP3"), false), Code::AlreadyOpen);
  EXPECT_EQ(q.open(1, name("LOCKED/MP3"), false), Code::Ok);
  EXPECT_EQ(p.close(2), Code::Ok);
  EXPECT_EQ(q.open(2, name("ORIG/MP3"), false), Code::Ok);
  EXPECT_EQ(p.open(2, name("ORIG/MP3"), true), Code::AlreadyOpen);
  EXPECT_EQ(p.open(2, name("ORIG/MP3"), false), Code::Ok);
}

TEST_F(AssetChannels, ReadFollowsTheRecordPointer) {
  Channels p(store.get(), open_files, {});
  std::vector<Value> v;
  EXPECT_EQ(p.read(0, 2, 1, v), Code::BadChannel);
  EXPECT_EQ(p.read(1, 2, 1, v), Code::NotOpen);
  ASSERT_EQ(p.open(1, name("ORIG/MP3"), false), Code::Ok);
  EXPECT_EQ(p.read(1, 2, 1, v), Code::NoStructure);
  ASSERT_TRUE(p.define(2, {{FieldType::Integer, 2}}));
  EXPECT_EQ(p.read(1, 2, 1, v), Code::Format);  // one field against five
  ASSERT_TRUE(p.define(2, kOrigins));           // a structure defined again is replaced
  EXPECT_EQ(p.read(1, 2, 0, v), Code::NoRecord);
  EXPECT_EQ(p.read(1, 2, 4, v), Code::NoRecord);
  EXPECT_EQ(p.read(1, 2, 3, v), Code::Ok);
  EXPECT_EQ(v, (std::vector<Value>{{2, {}}, {0, "Z"}, {-12.5, {}}, {0, "   "}, {0, {}}}));
  EXPECT_EQ(p.read(1, 2, std::nullopt, v), Code::EndOfFile);  // after record 3 of 3
  EXPECT_EQ(p.read(1, 2, 1, v), Code::Ok);
  EXPECT_EQ(p.read(1, 2, std::nullopt, v), Code::Ok);  // record 2
  EXPECT_EQ(p.read(1, 2, 9, v), Code::NoRecord);       // a failed read leaves the pointer
  EXPECT_EQ(p.read(1, 2, std::nullopt, v), Code::Ok);  // record 3
  EXPECT_EQ(v[0].number, 2);
  EXPECT_FALSE(p.define(0, kOrigins));
  EXPECT_FALSE(p.define(17, kOrigins));
  EXPECT_FALSE(p.define(1, {}));
}

TEST_F(AssetChannels, WriteGoesToTheDeviceAtOnce) {
  Channels p(store.get(), open_files, {});
  ASSERT_TRUE(p.define(2, kOrigins));
  const std::vector<Value> row = {{7, {}}, {0, "X"}, {0.5, {}}, {0, "AB"}, {1.5, {}}};
  ASSERT_EQ(p.open(1, name("ORIG/MP3"), false), Code::Ok);
  EXPECT_EQ(p.write(1, 2, 1, row), Code::Illegal);  // opened for reading
  ASSERT_EQ(p.close(1), Code::Ok);
  ASSERT_EQ(p.open(1, name("ORIG/MP3"), true), Code::Ok);
  EXPECT_EQ(p.write(1, 3, 1, row), Code::NoStructure);
  EXPECT_EQ(p.write(1, 2, 4, row), Code::NoRecord);
  std::vector<Value> wide = row;
  wide[0].number = 40000;  // more than IN holds
  EXPECT_EQ(p.write(1, 2, 2, wide), Code::Format);
  EXPECT_EQ(p.write(1, 2, std::nullopt, row), Code::Ok);  // record 1
  EXPECT_EQ(p.write(1, 2, std::nullopt, row), Code::Ok);  // record 2
  File f;
  ASSERT_EQ(store->load(name("ORIG/MP3"), f), Code::Ok);
  EXPECT_EQ(number(f, 1, 0), 7);
  EXPECT_EQ(chars(f, 2, 3), "AB ");
  EXPECT_EQ(number(f, 3, 0), 2);  // untouched
  std::vector<Value> back;
  EXPECT_EQ(p.read(1, 2, std::nullopt, back), Code::Ok);  // record 3: read and write share the pointer
  EXPECT_EQ(back[2].number, -12.5);
  EXPECT_EQ(p.write(1, 2, std::nullopt, row), Code::EndOfFile);
}

TEST_F(AssetChannels, CloseOneOrAll) {
  Channels p(store.get(), open_files, {});
  EXPECT_EQ(p.close(0), Code::BadChannel);
  EXPECT_EQ(p.close(1), Code::ChannelState);  // "channel still closed"
  EXPECT_EQ(p.close_all(), Code::Ok);         // nothing open: no error
  ASSERT_EQ(p.open(1, name("ORIG/MP3"), true), Code::Ok);
  ASSERT_EQ(p.open(2, name("LOCKED/MP3"), false), Code::Ok);
  EXPECT_EQ(p.close_all(), Code::Ok);
  Channels q(store.get(), open_files, {});
  EXPECT_EQ(q.open(1, name("ORIG/MP3"), true), Code::Ok);  // released
  {
    Channels r(store.get(), open_files, {});
    EXPECT_EQ(r.open(1, name("LOCKED/MP3"), false), Code::Ok);
  }
  EXPECT_EQ(q.remove(name("ORIG/MP3")), Code::AlreadyOpen);
  EXPECT_EQ(q.close(1), Code::Ok);
}

TEST_F(AssetChannels, CreateAndDelete) {
  Channels p(store.get(), open_files, {.channels = 1});
  EXPECT_EQ(p.create(2, name("PUNTXZ/MP3"), 20), Code::NoStructure);
  const Layout layout = {
      {FieldType::Chars, 1}, {FieldType::LongReal, 8}, {FieldType::Chars, 1}, {FieldType::LongReal, 8}};
  ASSERT_TRUE(p.define(2, layout));
  EXPECT_EQ(p.create(2, name("PUNTXZ/MP3"), 0), Code::Illegal);
  EXPECT_EQ(p.create(2, name("PUNTXZ/MP3"), 32768), Code::Illegal);
  EXPECT_EQ(p.create(2, name("PUNTXZ/MP5"), 20), Code::BadDevice);
  EXPECT_EQ(p.create(2, name("PUNTXZ/MP3"), 20), Code::Ok);
  EXPECT_EQ(p.create(2, name("PUNTXZ/MP3"), 20), Code::Exists);
  File f;
  ASSERT_EQ(store->load(name("PUNTXZ/MP3"), f), Code::Ok);
  EXPECT_EQ(f, blank_file(layout, 20));
  ASSERT_EQ(p.open(1, name("ORIG/MP3"), false), Code::Ok);  // the one channel taken
  EXPECT_EQ(p.create(2, name("OTHER/MP3"), 1), Code::NoChannel);
  EXPECT_EQ(p.remove(name("PUNTXZ/MP3")), Code::NoChannel);
  ASSERT_EQ(p.close(1), Code::Ok);
  EXPECT_EQ(p.remove(name("NONE/MP3")), Code::NotFound);
  EXPECT_EQ(p.remove(name("LOCKED/MP3")), Code::Protected);
  EXPECT_EQ(p.remove(name("PUNTXZ/MP3")), Code::Ok);
  EXPECT_EQ(store->load(name("PUNTXZ/MP3"), f), Code::NotFound);
  // A damaged file can be deleted.
  std::FILE* out = std::fopen((box.dir() / "MP3" / "BAD.nca").c_str(), "wb");
  std::fputs("NCAF", out);
  std::fclose(out);
  EXPECT_EQ(p.open(1, name("BAD/MP3"), false), Code::Logical);
  EXPECT_EQ(p.remove(name("BAD/MP3")), Code::Ok);
}

}  // namespace
}  // namespace ncc::asset
