/*
 * fb89_count.c - QEMU 7.2 TCG plugin (API version 1) that counts the
 * instructions a single-threaded m68k linux-user guest executes, grouped
 * by an "instruction class" key derived from the disassembly text, and
 * split into phases chosen by the guest with syscall(0xfb89, phase).
 *
 * Build:  gcc -O2 -shared -fPIC -Wall -Wextra -o libfb89_count.so fb89_count.c
 * Run:    qemu-m68k -cpu m68020 -plugin ./libfb89_count.so,out=FILE prog args
 *
 * Counting uses inline per-block counters only: every translated block gets
 * a record (class histogram of its instructions) and one inline ADD_U64 on
 * the record's execution counter.  At each phase change and at exit the
 * records are multiplied out into the current phase's totals and their
 * counters are zeroed.  See README.md for the key grammar and output format.
 *
 * Plain C11 + libc; no glib.  The few plugin API declarations used are
 * written out below (they match include/qemu/qemu-plugin.h of QEMU v7.2.0,
 * QEMU_PLUGIN_VERSION 1).
 *
 * Why one file of ~780 lines: QEMU loads a plugin as one shared object, and
 * this one is built with a single compiler call outside fb89's libraries
 * (README.md); its parts -- API declarations, the operand classifier, the
 * block records, the JSON writer -- are marked by section comments below.
 */
#define _POSIX_C_SOURCE 200809L /* getpid, pid_t under -std=c11 */
#include <inttypes.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* ---- QEMU 7.2 plugin API (version 1): only what this file uses ---------- */

#define QEMU_PLUGIN_EXPORT __attribute__((visibility("default")))

typedef uint64_t qemu_plugin_id_t;

typedef struct qemu_info_t {
    const char *target_name;
    struct {
        int min;
        int cur;
    } version;
    bool system_emulation;
    union {
        struct {
            int smp_vcpus;
            int max_vcpus;
        } system;
    };
} qemu_info_t;

struct qemu_plugin_tb;
struct qemu_plugin_insn;

enum qemu_plugin_op {
    QEMU_PLUGIN_INLINE_ADD_U64 = 0,
};

typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id,
                                               struct qemu_plugin_tb *tb);
typedef void (*qemu_plugin_vcpu_syscall_cb_t)(qemu_plugin_id_t id,
                                              unsigned int vcpu_index,
                                              int64_t num, uint64_t a1,
                                              uint64_t a2, uint64_t a3,
                                              uint64_t a4, uint64_t a5,
                                              uint64_t a6, uint64_t a7,
                                              uint64_t a8);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id,
                                           qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb,
                                              enum qemu_plugin_op op,
                                              void *ptr, uint64_t imm);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb,
                                                 size_t idx);
size_t qemu_plugin_insn_size(const struct qemu_plugin_insn *insn);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);
char *qemu_plugin_insn_disas(const struct qemu_plugin_insn *insn);
void qemu_plugin_register_vcpu_syscall_cb(qemu_plugin_id_t id,
                                          qemu_plugin_vcpu_syscall_cb_t cb);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id,
                                    qemu_plugin_udata_cb_t cb, void *userdata);
void qemu_plugin_outs(const char *string);

QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;

/* ---- configuration ------------------------------------------------------- */

#define FB89_MARKER_SYSCALL 0xfb89
#define FB89_NPHASES 16
#define KEY_MAX 192

/* ---- small utilities ----------------------------------------------------- */

/*
 * Errors and warnings: qemu_plugin_outs() only reaches the terminal when
 * QEMU runs with "-d plugin", so also write them to stderr (they appear
 * twice under "-d plugin").
 */
static void report(const char *msg)
{
    qemu_plugin_outs(msg);
    fputs(msg, stderr);
    fflush(stderr);
}

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) {
        report("fb89_count: out of memory\n");
        abort();
    }
    return p;
}

static void *xrealloc(void *old, size_t n)
{
    void *p = realloc(old, n ? n : 1);
    if (!p) {
        report("fb89_count: out of memory\n");
        abort();
    }
    return p;
}

static char *xstrdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = xmalloc(n);
    memcpy(p, s, n);
    return p;
}

/* ---- class table: key string <-> dense id (open addressing) ------------- */

static char **cls_keys;        /* id -> key */
static uint32_t cls_n;         /* number of classes */
static uint32_t cls_cap;       /* capacity of cls_keys and per-phase arrays */
static int32_t *cls_hash;      /* slot -> id, -1 empty */
static uint32_t cls_hash_cap;  /* power of two */

/* Per-phase totals. */
static uint64_t *phase_cls[FB89_NPHASES]; /* [phase][class id] */
static uint64_t phase_insns[FB89_NPHASES];
static uint64_t phase_bytes[FB89_NPHASES];
static uint64_t phase_entered[FB89_NPHASES];
static unsigned cur_phase;

static uint32_t hash_str(const char *s)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    for (; *s; s++) {
        h ^= (unsigned char)*s;
        h *= 16777619u;
    }
    return h;
}

static void cls_rehash(uint32_t newcap)
{
    free(cls_hash);
    cls_hash = xmalloc(sizeof(int32_t) * newcap);
    for (uint32_t i = 0; i < newcap; i++) {
        cls_hash[i] = -1;
    }
    cls_hash_cap = newcap;
    for (uint32_t id = 0; id < cls_n; id++) {
        uint32_t s = hash_str(cls_keys[id]) & (newcap - 1);
        while (cls_hash[s] >= 0) {
            s = (s + 1) & (newcap - 1);
        }
        cls_hash[s] = (int32_t)id;
    }
}

static uint32_t cls_intern(const char *key)
{
    if (cls_hash_cap == 0) {
        cls_rehash(256);
    }
    uint32_t s = hash_str(key) & (cls_hash_cap - 1);
    while (cls_hash[s] >= 0) {
        if (strcmp(cls_keys[cls_hash[s]], key) == 0) {
            return (uint32_t)cls_hash[s];
        }
        s = (s + 1) & (cls_hash_cap - 1);
    }
    /* new class */
    if (cls_n == cls_cap) {
        uint32_t ncap = cls_cap ? cls_cap * 2 : 128;
        cls_keys = xrealloc(cls_keys, sizeof(char *) * ncap);
        for (int p = 0; p < FB89_NPHASES; p++) {
            phase_cls[p] = xrealloc(phase_cls[p], sizeof(uint64_t) * ncap);
            memset(phase_cls[p] + cls_cap, 0,
                   sizeof(uint64_t) * (ncap - cls_cap));
        }
        cls_cap = ncap;
    }
    uint32_t id = cls_n++;
    cls_keys[id] = xstrdup(key);
    if ((uint64_t)cls_n * 2 > cls_hash_cap) {
        cls_rehash(cls_hash_cap * 2);
    } else {
        cls_hash[s] = (int32_t)id;
    }
    return id;
}

/* ---- operand classification (MIT syntax from QEMU's m68k disassembler) -- */

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

/* Build the class key for one disassembly string into out[KEY_MAX]. */
static void make_key(const char *dis, char *out)
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
        snprintf(out, KEY_MAX, "%s", mn);
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
        if (o + cl + 2 < KEY_MAX) {
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

/* ---- per-block records ---------------------------------------------------- */

struct pair {
    uint32_t cls;
    uint32_t cnt;
};

struct block {
    uint64_t exec;      /* incremented inline by the generated code */
    uint32_t ninsns;
    uint32_t bytes;
    uint32_t npairs;
    struct pair p[];
};

static struct block **blocks;
static size_t nblocks, blocks_cap;
static uint64_t blocks_translated;

static const char *out_path;
static FILE *dump_fp;          /* optional dump=PATH: per-insn key log */
static bool multi_vcpu;
static pid_t install_pid;     /* a forked guest child must not write */
static uint64_t bad_markers;
static FILE *phase_fp; /* phase=PATH: the current phase, rewritten at each marker */

static void vcpu_tb_trans(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    size_t n = qemu_plugin_tb_n_insns(tb);
    struct pair tmp_small[64];
    struct pair *tmp = n <= 64 ? tmp_small : xmalloc(sizeof(struct pair) * n);
    uint32_t npairs = 0;
    uint64_t bytes = 0;
    char key[KEY_MAX];

    for (size_t i = 0; i < n; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        char *dis = qemu_plugin_insn_disas(insn);
        make_key(dis, key);
        if (dump_fp) {
            fprintf(dump_fp, "%08" PRIx64 "\t%s\t%s\n",
                    qemu_plugin_insn_vaddr(insn), key, dis ? dis : "");
        }
        free(dis);
        bytes += qemu_plugin_insn_size(insn);
        uint32_t c = cls_intern(key);
        uint32_t j;
        for (j = 0; j < npairs; j++) {
            if (tmp[j].cls == c) {
                tmp[j].cnt++;
                break;
            }
        }
        if (j == npairs) {
            tmp[npairs].cls = c;
            tmp[npairs].cnt = 1;
            npairs++;
        }
    }

    struct block *b = xmalloc(sizeof(struct block) +
                              sizeof(struct pair) * npairs);
    b->exec = 0;
    b->ninsns = (uint32_t)n;
    b->bytes = (uint32_t)bytes;
    b->npairs = npairs;
    memcpy(b->p, tmp, sizeof(struct pair) * npairs);
    if (tmp != tmp_small) {
        free(tmp);
    }
    if (nblocks == blocks_cap) {
        blocks_cap = blocks_cap ? blocks_cap * 2 : 4096;
        blocks = xrealloc(blocks, sizeof(*blocks) * blocks_cap);
    }
    blocks[nblocks++] = b;
    blocks_translated++;

    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64,
                                             &b->exec, 1);
}

/* Multiply out all block counters into the current phase; zero them. */
static void flush_counts(void)
{
    uint64_t *tot = phase_cls[cur_phase];
    uint64_t insns = 0, bytes = 0;
    for (size_t i = 0; i < nblocks; i++) {
        struct block *b = blocks[i];
        uint64_t e = b->exec;
        if (!e) {
            continue;
        }
        b->exec = 0;
        insns += e * b->ninsns;
        bytes += e * b->bytes;
        for (uint32_t j = 0; j < b->npairs; j++) {
            tot[b->p[j].cls] += e * b->p[j].cnt;
        }
    }
    phase_insns[cur_phase] += insns;
    phase_bytes[cur_phase] += bytes;
}

static void vcpu_syscall(qemu_plugin_id_t id, unsigned int vcpu_index,
                         int64_t num, uint64_t a1, uint64_t a2, uint64_t a3,
                         uint64_t a4, uint64_t a5, uint64_t a6, uint64_t a7,
                         uint64_t a8)
{
    (void)id; (void)a2; (void)a3; (void)a4; (void)a5; (void)a6; (void)a7;
    (void)a8;
    if (vcpu_index != 0 && !multi_vcpu) {
        multi_vcpu = true;
        report("fb89_count: warning: guest uses more than one "
                         "vCPU/thread; counts are not reliable\n");
    }
    if (num != FB89_MARKER_SYSCALL) {
        return;
    }
    if (a1 >= FB89_NPHASES) {
        if (bad_markers++ == 0) {
            report("fb89_count: warning: marker phase out of range "
                             "0..15, ignored\n");
        }
        return;
    }
    flush_counts();
    cur_phase = (unsigned)a1;
    phase_entered[cur_phase]++;
    if (phase_fp) {
        /* the phase so far, for whoever must say where a guest that dies stopped */
        rewind(phase_fp);
        fprintf(phase_fp, "%u\n", cur_phase);
        fflush(phase_fp);
    }
}

/* ---- output --------------------------------------------------------------- */

static void put_json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') {
            fputc('\\', f);
            fputc(c, f);
        } else if (c < 0x20) {
            fprintf(f, "\\u%04x", c);
        } else {
            fputc(c, f);
        }
    }
    fputc('"', f);
}

static int cmp_key_ids(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return strcmp(cls_keys[x], cls_keys[y]);
}

static void plugin_exit(qemu_plugin_id_t id, void *userdata)
{
    (void)id; (void)userdata;
    if (getpid() != install_pid) {
        return;   /* forked child of the guest: only the original writes */
    }
    flush_counts();
    if (dump_fp) {
        fclose(dump_fp);
        dump_fp = NULL;
    }

    FILE *f = fopen(out_path, "w");
    if (!f) {
        char msg[512];
        snprintf(msg, sizeof(msg), "fb89_count: cannot open %s for writing\n",
                 out_path);
        report(msg);
        return;
    }
    uint32_t *order = xmalloc(sizeof(uint32_t) * (cls_n ? cls_n : 1));
    for (uint32_t i = 0; i < cls_n; i++) {
        order[i] = i;
    }
    qsort(order, cls_n, sizeof(uint32_t), cmp_key_ids);

    uint64_t total = 0;
    for (int p = 0; p < FB89_NPHASES; p++) {
        total += phase_insns[p];
    }
    fprintf(f, "{\"tool\":\"fb89_count\",\"version\":1,"
               "\"guest_instructions\":%" PRIu64 ","
               "\"blocks_translated\":%" PRIu64 ","
               "\"multi_vcpu\":%s,\"bad_markers\":%" PRIu64 ",\n"
               " \"phases\":[",
            total, blocks_translated, multi_vcpu ? "true" : "false",
            bad_markers);
    bool firstp = true;
    for (int p = 0; p < FB89_NPHASES; p++) {
        if (phase_insns[p] == 0 && phase_entered[p] == 0) {
            continue;
        }
        fprintf(f, "%s\n  {\"phase\":%d,\"entered\":%" PRIu64
                   ",\"instructions\":%" PRIu64 ",\"bytes\":%" PRIu64
                   ",\"classes\":{",
                firstp ? "" : ",", p, phase_entered[p], phase_insns[p],
                phase_bytes[p]);
        firstp = false;
        bool firstc = true;
        for (uint32_t k = 0; k < cls_n; k++) {
            uint32_t c = order[k];
            uint64_t v = phase_cls[p][c];
            if (!v) {
                continue;
            }
            fputs(firstc ? "\n   " : ",\n   ", f);
            put_json_string(f, cls_keys[c]);
            fprintf(f, ":%" PRIu64, v);
            firstc = false;
        }
        fputs("}}", f);
    }
    fputs("\n ]}\n", f);
    free(order);
    if (fclose(f) != 0) {
        report("fb89_count: error writing output file\n");
    }
}

/* ---- install --------------------------------------------------------------- */

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id,
                                           const qemu_info_t *info,
                                           int argc, char **argv)
{
    const char *dump_path = NULL;

    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (strncmp(a, "out=", 4) == 0 && a[4]) {
            out_path = a + 4;
        } else if (strncmp(a, "dump=", 5) == 0 && a[5]) {
            dump_path = a + 5;
        } else if (strncmp(a, "phase=", 6) == 0 && a[6]) {
            phase_fp = fopen(a + 6, "w");
            if (!phase_fp) {
                report("fb89_count: cannot open phase= file for writing\n");
                return 1;
            }
        } else {
            char msg[512];
            snprintf(msg, sizeof(msg),
                     "fb89_count: unknown argument '%s' "
                     "(expected out=PATH [dump=PATH] [phase=PATH])\n", a);
            report(msg);
            return 1;
        }
    }
    if (!out_path) {
        report("fb89_count: missing required argument out=PATH\n");
        return 1;
    }
    if (info && info->system_emulation) {
        report("fb89_count: warning: written for linux-user "
                         "(qemu-m68k); system emulation is untested\n");
    }
    if (dump_path) {
        dump_fp = fopen(dump_path, "w");
        if (!dump_fp) {
            report("fb89_count: cannot open dump file\n");
            return 1;
        }
        setvbuf(dump_fp, NULL, _IOLBF, 0); /* survive guest crashes */
    }
    /* Check now that the output file can be created, so a bad path fails
       before the guest runs rather than at exit. */
    FILE *f = fopen(out_path, "w");
    if (!f) {
        report("fb89_count: cannot open out= file for writing\n");
        return 1;
    }
    fclose(f);

    install_pid = getpid();
    cur_phase = 0;
    phase_entered[0] = 1;
    qemu_plugin_register_vcpu_tb_trans_cb(id, vcpu_tb_trans);
    qemu_plugin_register_vcpu_syscall_cb(id, vcpu_syscall);
    qemu_plugin_register_atexit_cb(id, plugin_exit, NULL);
    return 0;
}
