#include "asset_channels.h"

namespace ncc::asset {

bool OpenFiles::can_open(const FileName& name, bool write) const {
  auto it = open_.find(name.text());
  if (it == open_.end()) return true;
  return !write && !it->second.writer;
}

void OpenFiles::opened(const FileName& name, bool write) {
  Opens& o = open_[name.text()];
  if (write)
    o.writer = true;
  else
    ++o.readers;
}

void OpenFiles::closed(const FileName& name, bool write) {
  auto it = open_.find(name.text());
  if (it == open_.end()) return;
  if (write)
    it->second.writer = false;
  else if (it->second.readers > 0)
    --it->second.readers;
  if (!it->second.writer && it->second.readers == 0) open_.erase(it);
}

Channels::Channels(Store* store, OpenFiles& open_files, const Settings& settings)
    : store_(store), open_files_(open_files), settings_(settings) {}

Channels::~Channels() {
  for (const auto& [channel, open] : channels_) open_files_.closed(open.name, open.write);
}

bool Channels::define(uint32_t structure, const Layout& layout) {
  if (structure < 1 || structure > settings_.structures || !well_formed(layout)) return false;
  structures_[structure] = layout;
  return true;
}

Code Channels::open(uint32_t channel, const FileName& name, bool write) {
  if (!store_) return Code::NotConfigured;
  if (channel < 1 || channel > settings_.channels) return Code::BadChannel;
  if (channels_.count(channel)) return Code::ChannelState;
  Open o{name, write, {}, 1};
  if (Code c = store_->load(name, o.file); c != Code::Ok) return c;
  if (write && o.file.write_protected) return Code::Protected;
  if (!open_files_.can_open(name, write)) return Code::AlreadyOpen;
  open_files_.opened(name, write);
  channels_.emplace(channel, std::move(o));
  return Code::Ok;
}

Code Channels::channel_file(uint32_t channel, Open*& open) {
  if (!store_) return Code::NotConfigured;
  if (channel < 1 || channel > settings_.channels) return Code::BadChannel;
  auto it = channels_.find(channel);
  if (it == channels_.end()) return Code::NotOpen;
  open = &it->second;
  return Code::Ok;
}

// §5.3.2.3: a record written is that one; none, the one after the last RED or WRT.
Code Channels::record_of(const Open& open, std::optional<uint32_t> record, uint32_t& r) const {
  if (record) {
    if (*record < 1 || *record > open.file.records) return Code::NoRecord;
    r = *record;
  } else {
    if (open.next > open.file.records) return Code::EndOfFile;
    r = open.next;
  }
  return Code::Ok;
}

Code Channels::read(uint32_t channel, uint32_t structure, std::optional<uint32_t> record, std::vector<Value>& out,
                    uint32_t* at) {
  Open* o = nullptr;
  if (Code c = channel_file(channel, o); c != Code::Ok) return c;
  auto s = structures_.find(structure);
  if (s == structures_.end()) return Code::NoStructure;
  if (s->second != o->file.layout) return Code::Format;
  uint32_t r = 0;
  if (Code c = record_of(*o, record, r); c != Code::Ok) return c;
  if (at) *at = r;
  out.clear();
  for (size_t i = 0; i < o->file.layout.size(); ++i)
    out.push_back(o->file.layout[i].type == FieldType::Chars ? Value{0, std::string(chars(o->file, r, i))}
                                                             : Value{number(o->file, r, i), {}});
  o->next = r + 1;
  return Code::Ok;
}

Code Channels::write(uint32_t channel, uint32_t structure, std::optional<uint32_t> record,
                     const std::vector<Value>& values, uint32_t* at) {
  Open* o = nullptr;
  if (Code c = channel_file(channel, o); c != Code::Ok) return c;
  auto s = structures_.find(structure);
  if (s == structures_.end()) return Code::NoStructure;
  if (!o->write) return Code::Illegal;
  if (s->second != o->file.layout || values.size() != s->second.size()) return Code::Format;
  uint32_t r = 0;
  if (Code c = record_of(*o, record, r); c != Code::Ok) return c;
  if (at) *at = r;
  File changed = o->file;
  for (size_t i = 0; i < values.size(); ++i) {
    const bool ok = changed.layout[i].type == FieldType::Chars ? set_chars(changed, r, i, values[i].chars)
                                                               : set_number(changed, r, i, values[i].number);
    if (!ok) return Code::Format;
  }
  if (Code c = store_->replace(o->name, changed); c != Code::Ok) return c;  // the file as it was
  o->file = std::move(changed);
  o->next = r + 1;
  return Code::Ok;
}

Code Channels::close(uint32_t channel) {
  Open* o = nullptr;
  if (Code c = channel_file(channel, o); c != Code::Ok) return c == Code::NotOpen ? Code::ChannelState : c;
  open_files_.closed(o->name, o->write);
  channels_.erase(channel);
  return Code::Ok;
}

Code Channels::close_all() {
  if (!store_) return Code::NotConfigured;
  for (const auto& [channel, open] : channels_) open_files_.closed(open.name, open.write);
  channels_.clear();
  return Code::Ok;
}

// CRE and CAN "presuppose a logical channel" (§5.3.2.6): one of the process's must
// be free.
Code Channels::create(uint32_t structure, const FileName& name, uint32_t records) {
  if (!store_) return Code::NotConfigured;
  if (channels_.size() >= settings_.channels) return Code::NoChannel;
  auto s = structures_.find(structure);
  if (s == structures_.end()) return Code::NoStructure;
  if (records < 1 || records > kMaxRecords) return Code::Illegal;
  return store_->create(name, blank_file(s->second, records));
}

Code Channels::remove(const FileName& name) {
  if (!store_) return Code::NotConfigured;
  if (channels_.size() >= settings_.channels) return Code::NoChannel;
  File f;
  Code c = store_->load(name, f);
  if (c == Code::Logical) return store_->remove(name);  // a damaged file can go (a link cannot)
  if (c != Code::Ok) return c;
  if (f.write_protected) return Code::Protected;
  if (open_files_.is_open(name)) return Code::AlreadyOpen;
  return store_->remove(name);
}

}  // namespace ncc::asset
