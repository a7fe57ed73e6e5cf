#include "gap8/elf_loader.h"

#include <fcntl.h>
#include <gelf.h>
#include <libelf.h>
#include <unistd.h>

#include <cstdint>
#include <vector>

#include "gap8/fault.h"

namespace gap8 {
namespace {

// Owns the file descriptor and the libelf handle.
class ElfFile {
 public:
  explicit ElfFile(const std::string& path) : path_(path) {
    if (elf_version(EV_CURRENT) == EV_NONE) Fail("libelf initialisation failed");
    fd_ = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) Fail("cannot open file");
    Begin(elf_begin(fd_, ELF_C_READ, nullptr));
  }
  // libelf reads the bytes in place: the file keeps its own copy.
  ElfFile(const std::string& name, std::span<const uint8_t> bytes)
      : path_(name), bytes_(bytes.begin(), bytes.end()) {
    if (elf_version(EV_CURRENT) == EV_NONE) Fail("libelf initialisation failed");
    Begin(elf_memory(bytes_.data(), bytes_.size()));
  }
  ~ElfFile() { Close(); }
  ElfFile(const ElfFile&) = delete;
  ElfFile& operator=(const ElfFile&) = delete;

  Elf* get() const { return elf_; }
  [[noreturn]] void Fail(const std::string& why) const { throw ElfError(path_ + ": " + why); }

 private:
  void Close() {
    if (elf_) elf_end(elf_);
    if (fd_ >= 0) close(fd_);
    elf_ = nullptr;
    fd_ = -1;
  }

  void Begin(Elf* elf) {
    elf_ = elf;
    if (!elf_ || elf_kind(elf_) != ELF_K_ELF) {
      Close();  // a throwing constructor never runs the destructor
      Fail("not an ELF file");
    }
  }

  std::string path_;
  std::vector<char> bytes_;
  int fd_ = -1;
  Elf* elf_ = nullptr;
};

void LoadSegments(const ElfFile& file, Memory& memory) {
  size_t count = 0;
  if (elf_getphdrnum(file.get(), &count) != 0) file.Fail("no program headers");
  size_t file_size = 0;
  const char* raw = elf_rawfile(file.get(), &file_size);
  for (size_t i = 0; i < count; ++i) {
    GElf_Phdr ph;
    if (!gelf_getphdr(file.get(), static_cast<int>(i), &ph)) file.Fail("bad program header");
    if (ph.p_type != PT_LOAD || ph.p_memsz == 0) continue;
    if (ph.p_filesz > ph.p_memsz || ph.p_offset + ph.p_filesz > file_size)
      file.Fail("truncated segment");
    const uint32_t addr = static_cast<uint32_t>(ph.p_paddr);
    // Checked before anything is allocated: a hostile size must not reach the allocator.
    if (ph.p_paddr != addr || ph.p_memsz > UINT32_MAX ||
        !memory.Span(addr, static_cast<uint32_t>(ph.p_memsz)))
      file.Fail("segment at " + Hex(addr) + " of " + std::to_string(ph.p_memsz) +
                " bytes is outside L1 and L2");
    std::vector<uint8_t> bytes(ph.p_memsz, 0);
    std::copy(raw + ph.p_offset, raw + ph.p_offset + ph.p_filesz, bytes.begin());
    memory.Write(addr, bytes.data(), static_cast<uint32_t>(bytes.size()));
  }
}

void ReadSymbols(const ElfFile& file, ElfImage& image) {
  Elf_Scn* scn = nullptr;
  while ((scn = elf_nextscn(file.get(), scn)) != nullptr) {
    GElf_Shdr sh;
    if (!gelf_getshdr(scn, &sh) || sh.sh_type != SHT_SYMTAB || sh.sh_entsize == 0) continue;
    Elf_Data* data = elf_getdata(scn, nullptr);
    const size_t n = data ? sh.sh_size / sh.sh_entsize : 0;
    for (size_t i = 0; i < n; ++i) {
      GElf_Sym sym;
      if (!gelf_getsym(data, static_cast<int>(i), &sym)) continue;
      const char* name = elf_strptr(file.get(), sh.sh_link, sym.st_name);
      if (name && *name) image.symbols[name] = static_cast<uint32_t>(sym.st_value);
    }
  }
}

ElfImage Load(const ElfFile& file, Memory& memory) {
  if (gelf_getclass(file.get()) != ELFCLASS32) file.Fail("not a 32-bit ELF");
  GElf_Ehdr eh;
  if (!gelf_getehdr(file.get(), &eh)) file.Fail("bad ELF header");
  if (eh.e_machine != EM_RISCV) file.Fail("not a RISC-V ELF");
  if (eh.e_type != ET_EXEC) file.Fail("not an executable");
  LoadSegments(file, memory);
  ElfImage image;
  image.entry = static_cast<uint32_t>(eh.e_entry);
  ReadSymbols(file, image);
  return image;
}

}  // namespace

ElfImage LoadElf(const std::string& path, Memory& memory) { return Load(ElfFile(path), memory); }

ElfImage LoadElfBytes(const std::string& name, std::span<const uint8_t> bytes, Memory& memory) {
  return Load(ElfFile(name, bytes), memory);
}

}  // namespace gap8
