/*
 * classify.c - the counting plugin's part for the 386 + 387 PC (period/plugin/isa.h): the
 * Intel 80386 with its 80387, run as 32-bit code under qemu-i386.
 *
 * Keys come from QEMU's disassembly (AT&T syntax): the mnemonic as QEMU prints it, size
 * suffix included ("movl", "addb", "fldl", "fmulp"), a REP or LOCK prefix joined to it
 * ("rep_movsl"), then the operands' kinds, which is what the 386's and 387's clock tables
 * depend on:
 *
 *   reg     a general register (%eax, %al, %ax ...)
 *   mem     a memory operand with at most a base register or a displacement
 *   memi    a memory operand with an index register (the 386 adds a clock for base + index)
 *   imm     an immediate ($...)
 *   st0     the 387's stack top, %st or %st(0)
 *   sti     another 387 register, %st(i)
 *   seg     a segment register (%es, %gs ...)
 *   target  a branch or call destination given as an address
 *
 * An indirect branch or call ("*%eax", "*0x1c(%ebx)") keys its operand as reg or mem. A
 * string instruction under REP is counted once an iteration: QEMU runs each iteration as an
 * execution of the instruction (README.md says how the profile prices it).
 */
#include <ctype.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "period/plugin/isa.h"

static bool is_prefix(const char *word, size_t n)
{
    static const char *const prefixes[] = {"rep", "repe", "repz", "repne", "repnz", "lock"};
    for (size_t i = 0; i < sizeof(prefixes) / sizeof(prefixes[0]); i++) {
        if (strlen(prefixes[i]) == n && strncmp(word, prefixes[i], n) == 0) {
            return true;
        }
    }
    return false;
}

/* Branches and calls, whose bare address operand is a target, not a memory operand. */
static bool is_transfer(const char *mnemonic)
{
    return mnemonic[0] == 'j' || strncmp(mnemonic, "call", 4) == 0 ||
           strncmp(mnemonic, "loop", 4) == 0;
}

/* The kind of one operand, text [s, e). */
static const char *operand_kind(const char *s, const char *e, bool transfer)
{
    while (s < e && isspace((unsigned char)*s)) {
        s++;
    }
    while (e > s && isspace((unsigned char)e[-1])) {
        e--;
    }
    if (s < e && *s == '*') { /* indirect branch or call */
        s++;
        transfer = false;
    }
    if (s == e) {
        return "other";
    }
    if (*s == '$') {
        return "imm";
    }
    if (e - s >= 3 && strncmp(s, "%st", 3) == 0) { /* %st, %st(0) .. %st(7) */
        return e - s == 3 || (e - s == 6 && s[4] == '0') ? "st0" : "sti";
    }
    const char *paren = memchr(s, '(', (size_t)(e - s));
    if (*s == '%' && !paren) {
        const char *colon = memchr(s, ':', (size_t)(e - s));
        if (colon) { /* %gs:0x10: a memory operand with a segment override */
            return "mem";
        }
        if (e - s == 3 && s[2] == 's' && strchr("cdefgs", s[1])) {
            return "seg";
        }
        return "reg";
    }
    if (paren) {
        /* (base, index, scale): an index register is there when a comma follows one */
        const char *close = memchr(paren, ')', (size_t)(e - paren));
        const char *comma = close ? memchr(paren, ',', (size_t)(close - paren)) : NULL;
        if (comma) {
            const char *p = comma + 1;
            while (p < close && isspace((unsigned char)*p)) {
                p++;
            }
            if (p < close && *p == '%') {
                return "memi";
            }
        }
        return "mem";
    }
    /* a bare number or symbol: a branch's target, else an absolute address */
    return transfer ? "target" : "mem";
}

static void make_key(const struct fb89_insn *insn, char *key)
{
    const char *d = insn->disas ? insn->disas : "";
    size_t k = 0;
    while (*d && isspace((unsigned char)*d)) {
        d++;
    }
    /* the mnemonic, and the one after a prefix */
    for (int word = 0; word < 2; word++) {
        const char *w = d;
        while (*d && !isspace((unsigned char)*d)) {
            d++;
        }
        const size_t n = (size_t)(d - w);
        if (word == 1 && n == 0) {
            break;
        }
        if (word == 1) {
            key[k++] = '_';
        }
        for (size_t i = 0; i < n && k + 1 < FB89_KEY_MAX; i++) {
            key[k++] = w[i];
        }
        while (*d && isspace((unsigned char)*d)) {
            d++;
        }
        if (!is_prefix(w, n)) {
            break;
        }
    }
    if (k == 0) {
        snprintf(key, FB89_KEY_MAX, "(bad)");
        return;
    }
    key[k] = 0;
    const char *mnemonic = key;
    const char *joined = strrchr(key, '_');
    if (joined) {
        mnemonic = joined + 1;
    }
    const bool transfer = is_transfer(mnemonic);
    /* the operands, split at commas outside parentheses */
    bool first = true;
    while (*d) {
        const char *s = d;
        int depth = 0;
        while (*d && (depth > 0 || *d != ',')) {
            depth += *d == '(' ? 1 : *d == ')' ? -1 : 0;
            d++;
        }
        const char *kind = operand_kind(s, d, transfer);
        const int wrote = snprintf(key + k, FB89_KEY_MAX - k, "%s%s", first ? " " : ",", kind);
        if (wrote < 0 || (size_t)wrote >= FB89_KEY_MAX - k) {
            break;
        }
        k += (size_t)wrote;
        first = false;
        if (*d == ',') {
            d++;
        }
    }
}

static const char *const targets[] = {"i386", NULL};

const struct fb89_isa fb89_isa_x86 = {
    .name = "x86",
    .qemu_targets = targets,
    .make_key = make_key,
};
