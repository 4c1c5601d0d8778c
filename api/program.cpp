#include "internal.h"
#include "runtime/machine_interface_sink.h"

namespace ncc::api {

namespace {

constexpr uint32_t kErrorLimit = 100;  // as `ncc`'s

Severity severity_of(ncc::Severity s) {
  switch (s) {
    case ncc::Severity::Note: return Severity::Note;
    case ncc::Severity::Info: return Severity::Info;
    case ncc::Severity::Warning: return Severity::Warning;
    case ncc::Severity::Error: return Severity::Error;
  }
  return Severity::Error;
}

// The program of a session whose module compiled or loaded, if nothing was an error.
Result<Program> program_of(Session& s, std::optional<vm::Module> module) {
  if (!module || s.diags.has_errors()) return Result<Program>(diagnostics_of(s));
  auto impl = std::make_shared<Program::Impl>();
  impl->module = std::move(*module);
  for (const std::string& path : impl->module.source_map.files)
    for (uint32_t i = 0; i < s.sources.size(); ++i)
      if (s.sources.file(i).path() == path && !s.sources.file(i).text().empty()) {
        impl->sources.emplace_back(path, std::string(s.sources.file(i).text()));
        break;
      }
  return Result<Program>(ProgramAccess::make(std::move(impl)), diagnostics_of(s));
}

// A source file's program, as `ncc compile` makes it: compiled, and run dry.
std::optional<vm::Module> compiled(Session& s, uint32_t file, const std::string& dialect) {
  std::optional<vm::Module> m = compile_source(s, file, dialect);
  if (m && !s.diags.limit_reached()) dry_run(s, *m, RunSettings{});
  return m;
}

Result<Program> failed(Session& s) { return Result<Program>(diagnostics_of(s)); }

}  // namespace

std::vector<Diagnostic> diagnostics_of(const Session& s) {
  const std::vector<ncc::Diagnostic> list = diagnostics_in_order(s);
  std::vector<Diagnostic> out;
  out.reserve(list.size());
  for (const ncc::Diagnostic& d : list) {
    Diagnostic v;
    v.severity = severity_of(d.severity);
    v.code = diag_code(d.id);
    v.message = d.message;
    if (d.range.valid()) v.location = {s.sources.file(d.range.file).path(), d.range.line, d.range.col};
    v.text = format_text(d, s.sources);
    out.push_back(std::move(v));
  }
  return out;
}

Program::Program(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Result<Program> Program::compile(std::string_view text, const std::string& name, const CompileOptions& options) {
  Session s(kErrorLimit);
  s.library = options.library;
  if (!options.profile.empty() && !load_profile(s, options.profile)) return failed(s);
  const uint32_t file = s.sources.add(name, program_text(std::string(text)));
  std::optional<vm::Module> m = compiled(s, file, options.dialect);
  return program_of(s, std::move(m));
}

Result<Program> Program::compile_file(const std::string& path, const CompileOptions& options) {
  Session s(kErrorLimit);
  s.library = options.library;
  if (!options.profile.empty() && !load_profile(s, options.profile)) return failed(s);
  const auto input = read_input(s, path);
  if (!input) return failed(s);
  std::optional<vm::Module> m =
      input->first == FileKind::Bytecode ? load_module(s, input->second) : compiled(s, input->second, options.dialect);
  return program_of(s, std::move(m));
}

Result<Program> Program::load(const std::string& path) {
  Session s(kErrorLimit);
  const auto input = read_input(s, path);
  if (!input) return failed(s);
  if (input->first != FileKind::Bytecode) {
    s.diags.report(DiagId::BytecodeUnreadable, {}, path,
                   "it does not start as one (Program::compile_file reads source)");
    return failed(s);
  }
  return program_of(s, load_module(s, input->second));
}

Result<Program> Program::load_bytes(std::string_view bytes, const std::string& name) {
  Session s(kErrorLimit);
  return program_of(s, vm::read_module(bytes, name, s.diags));
}

std::string Program::bytes() const { return vm::write_module(impl_->module); }

std::string Program::dialect() const { return impl_->module.dialect; }

uint32_t Program::block_count() const { return impl_->module.source_map.size(); }

Block Program::block(uint32_t index) const { return block_of(impl_->module.source_map, index); }

std::optional<uint32_t> Program::block_at_line(uint32_t line) const {
  const SourceMap& map = impl_->module.source_map;
  std::optional<uint32_t> found;
  uint32_t index = 0;
  map.visit([&](const SourceBlock& b, const std::vector<WordPosition>&) {
    if (!found && b.file == 0 && b.line >= line) found = index;
    ++index;
  });
  return found;
}

}  // namespace ncc::api
