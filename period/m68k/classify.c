/*
 * classify.c - the counting plugin's part for the MC68020 + MC68881 (period/plugin/isa.h):
 * an instruction's class key from QEMU's m68k disassembly (MIT syntax), a mnemonic and its
 * operands' addressing classes, e.g. "movel disp,dreg" or "fmoved fpreg,fpreg". The key
 * grammar is in period/plugin/README.md; the profiles that price the keys are in
 * period/m68k/profiles/.
 */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "period/plugin/isa.h"

static bool str_in(const char *s, const char *const *list)
{
    for (; *list; list++) {
        if (strcmp(s, *list) == 0) {
            return true;
        }
    }
    return false;
}

/* Bcc/BRA/BSR with optional size suffix (s, w, l, b). */
static bool is_int_branch(const char *m)
{
    static const char *const cc[] = {
        "ra", "sr", "hi", "ls", "cc", "cs", "ne", "eq", "vc", "vs",
        "pl", "mi", "ge", "lt", "gt", "le", "hs", "lo", NULL
    };
    char buf[8];
    size_t n = strlen(m);
    if (m[0] != 'b' || n < 3 || n > 4) {
        return false;
    }
    memcpy(buf, m + 1, 2);
    buf[2] = '\0';
    if (!str_in(buf, cc)) {
        return false;
    }
    return n == 3 || strchr("swlb", m[3]) != NULL;
}

/* Mnemonics whose bare-number operands are branch targets. */
static bool is_branch_mnemonic(const char *m)
{
    return is_int_branch(m) ||
           strncmp(m, "db", 2) == 0 ||   /* DBcc */
           strncmp(m, "fb", 2) == 0 ||   /* FBcc */
           strncmp(m, "fdb", 3) == 0;    /* FDBcc */
}

static bool is_movem_mnemonic(const char *m)
{
    return strncmp(m, "movem", 5) == 0 || strncmp(m, "fmovem", 6) == 0;
}

/* Classify a bare register name (no '@'), e.g. "%d0", "%fp", "%fp3". */
static const char *classify_reg(const char *r, size_t n)
{
    if (n == 3 && r[0] == '%' && r[1] == 'd' && r[2] >= '0' && r[2] <= '7') {
        return "dreg";
    }
    if (n == 3 && r[0] == '%' && r[1] == 'a' && r[2] >= '0' && r[2] <= '7') {
        return "areg";
    }
    if ((n == 3 && strncmp(r, "%sp", 3) == 0) ||
        (n == 3 && strncmp(r, "%fp", 3) == 0)) {   /* %fp alone is a6 */
        return "areg";
    }
    if (n == 4 && strncmp(r, "%fp", 3) == 0 && r[3] >= '0' && r[3] <= '7') {
        return "fpreg";
    }
    if ((n == 5 && strncmp(r, "%fpcr", 5) == 0) ||
        (n == 5 && strncmp(r, "%fpsr", 5) == 0) ||
        (n == 6 && strncmp(r, "%fpiar", 6) == 0)) {
        return "fpcr";
    }
    return NULL;
}

static bool all_fpcr_list(const char *s, size_t n)
{
    size_t i = 0;
    while (i < n) {
        size_t j = i;
        while (j < n && s[j] != '/') {
            j++;
        }
        const char *c = classify_reg(s + i, j - i);
        if (!c || strcmp(c, "fpcr") != 0) {
            return false;
        }
        i = j + 1;
    }
    return true;
}

static bool is_number(const char *s, size_t n)
{
    size_t i = 0;
    if (i < n && s[i] == '-') {
        i++;
    }
    if (i >= n || s[i] < '0' || s[i] > '9') {
        return false;
    }
    for (; i < n; i++) {
        char c = s[i];
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') ||
              (c >= 'A' && c <= 'F') || c == 'x' || c == 'X')) {
            return false;
        }
    }
    return true;
}

/*
 * Classify one operand string s[0..n).  `branch`: mnemonic is a
 * Bcc/DBcc/FBcc/FDBcc; `movem`: mnemonic is movem/fmovem; `bitfield`:
 * mnemonic is bf* (offset/width print as bare numbers: "bftst %d0,29,3").
 */
static const char *classify_operand(const char *s, size_t n, bool branch,
                                    bool movem, bool bitfield)
{
    while (n && (s[0] == ' ' || s[0] == '\t')) {
        s++, n--;
    }
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t')) {
        n--;
    }
    if (n == 0) {
        /* address elided by the plugin disassembler (see make_key) */
        return branch ? "target" : "abs";
    }
    /* Bit-field suffix "{off:width}" (bfextu etc.): classify the base. */
    if (s[n - 1] == '}') {
        const char *b = memchr(s, '{', n);
        if (b && b > s) {
            n = (size_t)(b - s);
        }
    }
    if (s[0] == '#') {
        return "imm";
    }
    const char *at = memchr(s, '@', n);
    if (at) {
        size_t base = (size_t)(at - s);
        size_t rest = n - base - 1;       /* chars after '@' */
        const char *r = at + 1;
        bool pc = (base == 3 && strncmp(s, "%pc", 3) == 0) ||
                  (base == 4 && strncmp(s, "%zpc", 4) == 0);
        if (rest == 0) {
            return pc ? "pcrel" : "ind";
        }
        if (rest == 1 && r[0] == '+') {
            return "postinc";
        }
        if (rest == 1 && r[0] == '-') {
            return "predec";
        }
        if (r[0] == '(') {
            /* find matching ')' */
            size_t depth = 0, i;
            bool inner_sep = false;
            for (i = 0; i < rest; i++) {
                char c = r[i];
                if (c == '(') {
                    depth++;
                } else if (c == ')') {
                    if (--depth == 0) {
                        break;
                    }
                } else if (c == ',' || c == ':') {
                    inner_sep = true;
                }
            }
            bool more = i + 1 < rest;            /* e.g. ...)@(...) */
            if (base == 0 || (base > 1 && s[1] == 'z') || inner_sep || more) {
                return "index";                  /* indexed / mem-indirect */
            }
            return pc ? "pcrel" : "disp";
        }
        return "other";
    }
    if (s[0] == '%') {
        const char *c = classify_reg(s, n);
        if (c) {
            if (movem && strcmp(c, "fpcr") != 0) {
                return "reglist";
            }
            return c;
        }
        if (memchr(s, '/', n) || memchr(s, '-', n)) {
            return all_fpcr_list(s, n) ? "fpcr" : "reglist";
        }
        return "other";
    }
    /* Bare numbers: branch targets, or absolute memory addresses
       (possibly with a ":w" / ":l" size suffix). */
    {
        size_t m = n;
        if (m > 2 && s[m - 2] == ':' && (s[m - 1] == 'w' || s[m - 1] == 'l')) {
            m -= 2;
        }
        if (is_number(s, m)) {
            if (bitfield && m == n) {
                return "imm";
            }
            return (branch && m == n) ? "target" : "abs";
        }
    }
    return "other";
}

/* Build the class key for one disassembly string into out[FB89_KEY_MAX]. */
static void make_key_from_disas(const char *dis, char *out)
{
    size_t o = 0;
    char mn[32];
    size_t mlen = 0;

    if (!dis) {
        strcpy(out, "(nodisas)");
        return;
    }
    while (*dis == ' ' || *dis == '\t') {
        dis++;
    }
    while (dis[mlen] && dis[mlen] != ' ' && dis[mlen] != '\t') {
        mlen++;
    }
    if (mlen == 0) {
        strcpy(out, "(empty)");
        return;
    }
    if (mlen >= sizeof(mn)) {
        mlen = sizeof(mn) - 1;
    }
    memcpy(mn, dis, mlen);
    mn[mlen] = '\0';
    /* Data directives (undecodable words): no operand classes. */
    if (mn[0] == '.') {
        snprintf(out, FB89_KEY_MAX, "%s", mn);
        return;
    }
    memcpy(out, mn, mlen);
    o = mlen;

    /*
     * Operands follow the first blank.  QEMU's plugin disassembly prints
     * nothing for addresses it would hand to print_address_func (branch
     * targets, absolute addresses, "%pc@()" displacements), so an operand
     * field may be empty: "bnes ", "dbf %d6,", "pea ", "lea ,%a0".  A
     * mnemonic followed by a blank therefore always has >= 1 operand, and
     * a trailing comma means a trailing empty operand.
     */
    const char *p = dis + mlen;
    if (*p != ' ' && *p != '\t') {
        out[o] = '\0';             /* no operands, e.g. "rts" */
        return;
    }
    p++;
    bool branch = is_branch_mnemonic(mn);
    bool movem = is_movem_mnemonic(mn);
    bool bitfield = strncmp(mn, "bf", 2) == 0;
    bool first = true;
    for (;;) {
        /* split at top-level commas */
        const char *start = p;
        int depth = 0;
        while (*p && !(*p == ',' && depth == 0)) {
            if (*p == '(' || *p == '{') {
                depth++;
            } else if ((*p == ')' || *p == '}') && depth > 0) {
                depth--;
            }
            p++;
        }
        const char *c = classify_operand(start, (size_t)(p - start), branch,
                                         movem, bitfield);
        size_t cl = strlen(c);
        if (o + cl + 2 < FB89_KEY_MAX) {
            out[o++] = first ? ' ' : ',';
            memcpy(out + o, c, cl);
            o += cl;
        }
        first = false;
        if (*p != ',') {
            break;
        }
        p++;
    }
    out[o] = '\0';
}

static void make_key(const struct fb89_insn *insn, char *key)
{
    make_key_from_disas(insn->disas, key);
}

static const char *const qemu_targets[] = {"m68k", NULL};

const struct fb89_isa fb89_isa_m68k = {
    .name = "m68k",
    .qemu_targets = qemu_targets,
    .make_key = make_key,
};
