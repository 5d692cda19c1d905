// The 386 + 387 PC's classifier (period/x86/classify.c) on QEMU's own disassembly: each line
// below is an instruction as qemu-i386 prints it (capstone, AT&T syntax) and the key the
// grammar in period/plugin/README.md ("Class key grammar (x86)") gives it. The classifier is
// taken from the counting plugin as built, loaded without QEMU (its calls into QEMU are bound
// lazily and never made): the plugin is $FB89_COUNT_PLUGIN, else the one in the build tree.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "period/plugin/isa.h"

namespace {

const fb89_isa* x86_classifier() {
    static const fb89_isa* isa = []() -> const fb89_isa* {
        const char* given = std::getenv("FB89_COUNT_PLUGIN");
        const std::string path =
            given && *given ? given : FB89_BUILD_DIR "/period/plugin/libfb89_count.so";
        if (::access(path.c_str(), R_OK) != 0) return nullptr;
        void* plugin = ::dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
        if (!plugin) return nullptr;
        return static_cast<const fb89_isa*>(::dlsym(plugin, "fb89_isa_x86"));
    }();
    return isa;
}

std::string key(const char* disassembly) {
    fb89_insn insn{};
    insn.disas = disassembly;
    char out[FB89_KEY_MAX] = {};
    x86_classifier()->make_key(&insn, out);
    return out;
}

class PeriodX86Classify : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!x86_classifier()) GTEST_SKIP() << "the counting plugin is not built";
    }
};

TEST_F(PeriodX86Classify, QemuTargetIsI386) {
    EXPECT_STREQ(x86_classifier()->name, "x86");
    EXPECT_STREQ(x86_classifier()->qemu_targets[0], "i386");
}

TEST_F(PeriodX86Classify, GeneralRegistersImmediatesAndSegments) {
    EXPECT_EQ(key("addl $4, %esp"), "addl imm,reg");
    EXPECT_EQ(key("movb %al, %dl"), "movb reg,reg");
    EXPECT_EQ(key("movw %gs, %ax"), "movw seg,reg");
    EXPECT_EQ(key("imull $0x34, %eax, %edx"), "imull imm,reg,reg");
    EXPECT_EQ(key("retl"), "retl");
    EXPECT_EQ(key("nop"), "nop");
}

// The 386 adds a clock for an effective address with a base and an index: memi, not mem.
TEST_F(PeriodX86Classify, MemoryOperandsWithAndWithoutAnIndex) {
    EXPECT_EQ(key("movl 8(%ebp), %eax"), "movl mem,reg");
    EXPECT_EQ(key("movl %eax, (%ecx)"), "movl reg,mem");
    EXPECT_EQ(key("movl 0x80c1234, %eax"), "movl mem,reg");  // an absolute address
    EXPECT_EQ(key("movl %gs:0x14, %eax"), "movl mem,reg");   // a segment override
    EXPECT_EQ(key("movl (%esi,%ebx,4), %eax"), "movl memi,reg");
    EXPECT_EQ(key("movl 0x804a000(,%ebx,4), %eax"), "movl memi,reg");  // an index, no base
    EXPECT_EQ(key("movsbl (%eax,%edx), %ecx"), "movsbl memi,reg");
    EXPECT_EQ(key("leal (%eax,%eax), %edx"), "leal memi,reg");
}

// A branch's or call's address is its target; an indirect one keys its operand.
TEST_F(PeriodX86Classify, TransfersOfControl) {
    EXPECT_EQ(key("jne 0x80491a0"), "jne target");
    EXPECT_EQ(key("jmp 0x80491a0"), "jmp target");
    EXPECT_EQ(key("calll 0x8049679"), "calll target");
    EXPECT_EQ(key("calll *%gs:0x10"), "calll mem");
    EXPECT_EQ(key("jmpl *%eax"), "jmpl reg");
    EXPECT_EQ(key("jmpl *0x1c(%ebx)"), "jmpl mem");
}

// The 387's register stack: %st and %st(0) are its top, %st(1)..%st(7) the others.
TEST_F(PeriodX86Classify, The387sStack) {
    EXPECT_EQ(key("fldl 0x10(%esp)"), "fldl mem");
    EXPECT_EQ(key("fstpl (%eax,%edx,8)"), "fstpl memi");
    EXPECT_EQ(key("fld %st(0)"), "fld st0");
    EXPECT_EQ(key("fstp %st(0)"), "fstp st0");
    EXPECT_EQ(key("faddp %st(1)"), "faddp sti");
    EXPECT_EQ(key("fxch %st(1)"), "fxch sti");
    EXPECT_EQ(key("fmul %st(0), %st(2)"), "fmul st0,sti");
    EXPECT_EQ(key("fmul %st(2), %st"), "fmul sti,st0");
    EXPECT_EQ(key("fucomip %st(1), %st"), "fucomip sti,st0");
}

// A REP or LOCK prefix is joined to the mnemonic.
TEST_F(PeriodX86Classify, PrefixesJoinTheMnemonic) {
    EXPECT_EQ(key("rep stosb %al, %es:(%edi)"), "rep_stosb reg,mem");
    EXPECT_EQ(key("repne scasb %es:(%edi), %al"), "repne_scasb mem,reg");
    EXPECT_EQ(key("lock cmpxchgl %ecx, (%edx)"), "lock_cmpxchgl reg,mem");
}

TEST_F(PeriodX86Classify, NoDisassembly) {
    fb89_insn insn{};
    char out[FB89_KEY_MAX] = {};
    x86_classifier()->make_key(&insn, out);
    EXPECT_STREQ(out, "(bad)");
}

}  // namespace
