/*
 * count.c - QEMU 7.2 TCG plugin (API version 1) that counts the instructions a
 * single-threaded linux-user guest executes, grouped by an "instruction class" key,
 * and split into phases chosen by the guest with syscall(0xfb89, phase). The common
 * core of the period hosts' plugin: what differs by instruction set -- the class key
 * of an instruction, pseudo-classes such as register-window traps -- is in
 * period/<isa>/classify.c behind period/plugin/isa.h, chosen by QEMU's target name.
 *
 * Build:  gcc -O2 -shared -fPIC -Wall -Wextra -I. -o libfb89_count.so \
 *             period/plugin/count.c period/m68k/classify.c period/sparc/classify.c
 * Run:    qemu-m68k -cpu m68020 -plugin ./libfb89_count.so,out=FILE prog args
 *         qemu-sparc32plus -plugin ./libfb89_count.so,out=FILE prog args
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
 * Why one file of ~600 lines: QEMU loads a plugin as one shared object, built with a
 * single compiler call outside fb89's libraries (README.md); its parts -- API
 * declarations, the class table, the block records, the JSON writer -- are marked by
 * section comments below.
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

#include "period/plugin/isa.h"

/* ---- QEMU 7.2 plugin API (version 1): only what this file uses ---------- */

#define QEMU_PLUGIN_EXPORT __attribute__((visibility("default")))

typedef uint64_t qemu_plugin_id_t;

typedef struct qemu_info_t {
    const char* target_name;
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

enum qemu_plugin_cb_flags {
    QEMU_PLUGIN_CB_NO_REGS,
    QEMU_PLUGIN_CB_R_REGS,
    QEMU_PLUGIN_CB_RW_REGS,
};

typedef uint32_t qemu_plugin_meminfo_t;

enum qemu_plugin_mem_rw {
    QEMU_PLUGIN_MEM_R = 1,
    QEMU_PLUGIN_MEM_W,
    QEMU_PLUGIN_MEM_RW,
};

typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void* userdata);
typedef void (*qemu_plugin_vcpu_mem_cb_t)(unsigned int vcpu_index, qemu_plugin_meminfo_t info,
                                          uint64_t vaddr, void* userdata);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void* userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb* tb);
typedef void (*qemu_plugin_vcpu_syscall_cb_t)(qemu_plugin_id_t id, unsigned int vcpu_index,
                                              int64_t num, uint64_t a1, uint64_t a2, uint64_t a3,
                                              uint64_t a4, uint64_t a5, uint64_t a6, uint64_t a7,
                                              uint64_t a8);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb* tb, enum qemu_plugin_op op,
                                              void* ptr, uint64_t imm);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb* tb);
struct qemu_plugin_insn* qemu_plugin_tb_get_insn(const struct qemu_plugin_tb* tb, size_t idx);
size_t qemu_plugin_insn_size(const struct qemu_plugin_insn* insn);
const void* qemu_plugin_insn_data(const struct qemu_plugin_insn* insn);
void qemu_plugin_register_vcpu_mem_cb(struct qemu_plugin_insn* insn, qemu_plugin_vcpu_mem_cb_t cb,
                                      enum qemu_plugin_cb_flags flags, enum qemu_plugin_mem_rw rw,
                                      void* userdata);
bool qemu_plugin_mem_is_store(qemu_plugin_meminfo_t info);
unsigned int qemu_plugin_mem_size_shift(qemu_plugin_meminfo_t info);
void qemu_plugin_register_vcpu_insn_exec_cb(struct qemu_plugin_insn* insn,
                                            qemu_plugin_vcpu_udata_cb_t cb,
                                            enum qemu_plugin_cb_flags flags, void* userdata);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn* insn);
char* qemu_plugin_insn_disas(const struct qemu_plugin_insn* insn);
void qemu_plugin_register_vcpu_syscall_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_syscall_cb_t cb);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void* userdata);
void qemu_plugin_outs(const char* string);

QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;

/* ---- configuration ------------------------------------------------------- */

#define FB89_MARKER_SYSCALL 0xfb89
#define FB89_SEND_SYSCALL 0xfb8a
#define FB89_NPHASES 16
#define KEY_MAX FB89_KEY_MAX

/* ---- small utilities ----------------------------------------------------- */

/*
 * Errors and warnings: qemu_plugin_outs() only reaches the terminal when
 * QEMU runs with "-d plugin", so also write them to stderr (they appear
 * twice under "-d plugin").
 */
static void report(const char* msg) {
    qemu_plugin_outs(msg);
    fputs(msg, stderr);
    fflush(stderr);
}

static void* xmalloc(size_t n) {
    void* p = malloc(n ? n : 1);
    if (!p) {
        report("fb89_count: out of memory\n");
        abort();
    }
    return p;
}

static void* xrealloc(void* old, size_t n) {
    void* p = realloc(old, n ? n : 1);
    if (!p) {
        report("fb89_count: out of memory\n");
        abort();
    }
    return p;
}

static char* xstrdup(const char* s) {
    size_t n = strlen(s) + 1;
    char* p = xmalloc(n);
    memcpy(p, s, n);
    return p;
}

/* ---- class table: key string <-> dense id (open addressing) ------------- */

static char** cls_keys;       /* id -> key */
static uint32_t cls_n;        /* number of classes */
static uint32_t cls_cap;      /* capacity of cls_keys and per-phase arrays */
static int32_t* cls_hash;     /* slot -> id, -1 empty */
static uint32_t cls_hash_cap; /* power of two */

/* Per-phase totals. */
static uint64_t* phase_cls[FB89_NPHASES]; /* [phase][class id] */
static uint64_t phase_insns[FB89_NPHASES];
static uint64_t phase_bytes[FB89_NPHASES];
static uint64_t phase_entered[FB89_NPHASES];
static unsigned cur_phase;

/*
 * Send marks (syscall 0xfb8a, argument: the commands sent so far): at each, the current
 * phase's counts since the last mark (or since the phase was entered) are kept as a record,
 * so that the host cost model can price the instructions up to every send. The marking
 * code itself lies in [marks_lo, marks_hi), which the guest names with every phase marker;
 * blocks there are not counted.
 */
struct send_record {
    unsigned phase;
    uint64_t commands, insns;
    uint32_t n;         /* classes that changed */
    uint32_t* cls;      /* their ids */
    uint64_t* delta;    /* and how many more executions */
};
static struct send_record* sends;
static size_t nsends, sends_cap;
static uint64_t* send_base;   /* [class id]: the current phase's counts at the last mark */
static uint64_t send_base_insns;
static uint64_t marks_lo, marks_hi;

static uint32_t hash_str(const char* s) {
    uint32_t h = 2166136261u; /* FNV-1a */
    for (; *s; s++) {
        h ^= (unsigned char)*s;
        h *= 16777619u;
    }
    return h;
}

static void cls_rehash(uint32_t newcap) {
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

static uint32_t cls_intern(const char* key) {
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
        cls_keys = xrealloc(cls_keys, sizeof(char*) * ncap);
        for (int p = 0; p < FB89_NPHASES; p++) {
            phase_cls[p] = xrealloc(phase_cls[p], sizeof(uint64_t) * ncap);
            memset(phase_cls[p] + cls_cap, 0, sizeof(uint64_t) * (ncap - cls_cap));
        }
        send_base = xrealloc(send_base, sizeof(uint64_t) * ncap);
        memset(send_base + cls_cap, 0, sizeof(uint64_t) * (ncap - cls_cap));
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

/* ---- data caches ----------------------------------------------------------- */

/*
 * Direct-mapped, virtually indexed and tagged data caches (plugin option
 * cache=SIZE:LINE:POLICY, as many as asked for: every period machine's cache at once, so
 * the counts stay the same whatever profile prices them). POLICY is wb (write-back,
 * write-allocate: a store that misses fetches its line, as on the Sun-3/260 and
 * Sun-4/260) or wt (write-through, no write-allocate: a store that misses goes to memory
 * and invalidates the line at its index, as on the SPARCstations). Every load and store
 * the guest makes is looked up in each cache; the misses are counted per phase as
 * "@dcache_<SIZE/1024>k_<LINE>b_<POLICY>_read_miss" and "..._write_miss", and in a
 * write-back cache every miss that evicts a line written since it was filled as
 * "..._writeback" (the dirty line goes back to memory before the new one comes in). A host
 * profile prices the events of its own machine's cache and nothing for the others.
 * Instruction fetches are not simulated.
 */
#define FB89_MAX_CACHES 4

struct cache {
    uint32_t size, line, shift, sets;
    bool write_allocate;
    uint64_t* tags; /* line address + 1 per set; 0 = empty */
    uint8_t* dirty; /* per set: written since filled (write-back caches only) */
    uint64_t read_miss, write_miss, writeback;
    char read_key[64], write_key[64], writeback_key[64];
};

static struct cache caches[FB89_MAX_CACHES];
static unsigned ncaches;

static bool cache_option(const char* arg) {
    if (strncmp(arg, "cache=", 6) != 0) {
        return false;
    }
    char* end = NULL;
    unsigned long size = strtoul(arg + 6, &end, 10);
    if (!end || *end != ':') {
        return false;
    }
    unsigned long line = strtoul(end + 1, &end, 10);
    if (!end || *end != ':' || (strcmp(end + 1, "wb") != 0 && strcmp(end + 1, "wt") != 0)) {
        return false;
    }
    const char* policy = end + 1;
    if (ncaches == FB89_MAX_CACHES || line < 4 || size < line || (line & (line - 1)) ||
        (size & (size - 1)) || size > (1ul << 24)) {
        return false;
    }
    struct cache* c = &caches[ncaches++];
    c->size = (uint32_t)size;
    c->line = (uint32_t)line;
    c->write_allocate = policy[1] == 'b';
    c->shift = 0;
    while ((1u << c->shift) < c->line) {
        c->shift++;
    }
    c->sets = c->size / c->line;
    c->tags = xmalloc(sizeof(uint64_t) * c->sets);
    memset(c->tags, 0, sizeof(uint64_t) * c->sets);
    c->dirty = xmalloc(c->sets);
    memset(c->dirty, 0, c->sets);
    snprintf(c->read_key, sizeof(c->read_key), "@dcache_%luk_%lub_%s_read_miss", size / 1024, line,
             policy);
    snprintf(c->write_key, sizeof(c->write_key), "@dcache_%luk_%lub_%s_write_miss", size / 1024,
             line, policy);
    snprintf(c->writeback_key, sizeof(c->writeback_key), "@dcache_%luk_%lub_%s_writeback",
             size / 1024, line, policy);
    return true;
}

static void vcpu_mem(unsigned int vcpu_index, qemu_plugin_meminfo_t info, uint64_t vaddr,
                     void* userdata) {
    (void)vcpu_index;
    (void)userdata;
    const bool store = qemu_plugin_mem_is_store(info);
    const uint64_t last = vaddr + (1u << qemu_plugin_mem_size_shift(info)) - 1;
    for (unsigned i = 0; i < ncaches; i++) {
        struct cache* c = &caches[i];
        for (uint64_t l = vaddr >> c->shift; l <= last >> c->shift; l++) {
            const uint64_t set = l & (c->sets - 1);
            uint64_t* tag = &c->tags[set];
            if (*tag == l + 1) {
                if (store && c->write_allocate) {
                    c->dirty[set] = 1;
                }
                continue;
            }
            if (!store) {
                c->read_miss++;
            } else {
                c->write_miss++;
            }
            if (!store || c->write_allocate) {
                /* the line comes in; a dirty one it replaces goes back first */
                c->writeback += c->dirty[set];
                *tag = l + 1;
                c->dirty[set] = store;
            } else {
                *tag = 0; /* write-through, no allocate: the store invalidates the line */
            }
        }
    }
}

/* ---- per-block records ---------------------------------------------------- */

struct pair {
    uint32_t cls;
    uint32_t cnt;
};

/* What each instruction of a block adds, for blocks with watched instructions: QEMU may
   stop such a block at a watched instruction and restart there (see vcpu_insn_event). */
struct insn_record {
    uint32_t cls;   /* its class */
    uint32_t extra; /* a pseudo-class counted at it (block_extras), or UINT32_MAX */
    uint32_t bytes;
};

struct block {
    uint64_t exec;             /* incremented inline by the generated code */
    uint64_t vaddr;            /* of its first instruction */
    uint64_t annul;            /* address of the annulling branch ending it, else 0 */
    uint64_t cut;              /* times it was stopped short (before its branch) by a QEMU trap */
    struct insn_record* insns; /* per instruction, or NULL when nothing in it is watched */
    uint32_t ninsns;
    uint32_t bytes;
    uint32_t npairs;
    struct pair p[];
};

/* A watched instruction: the block it is in and its place there. */
struct watch {
    struct block* b;
    uint64_t vaddr;
    uint32_t index;
    int event;
};

static struct block** blocks;
static size_t nblocks, blocks_cap;
static uint64_t blocks_translated;

static const char* out_path;
static FILE* dump_fp; /* optional dump=PATH: per-insn key log */
static bool multi_vcpu;
static pid_t install_pid; /* a forked guest child must not write */
static uint64_t bad_markers;
static FILE* phase_fp;             /* phase=PATH: the current phase, rewritten at each marker */
static const struct fb89_isa* isa; /* chosen at install by QEMU's target name */
static uint32_t annulled_cls;      /* class id of "@annulled_slot" */

/* A block's pairs while it is translated: one entry per class, with its count. */
struct pairs {
    struct pair* p;
    uint32_t n;
};

static void pairs_add(struct pairs* ps, uint32_t c, uint32_t k) {
    for (uint32_t j = 0; j < ps->n; j++) {
        if (ps->p[j].cls == c) {
            ps->p[j].cnt += k;
            return;
        }
    }
    ps->p[ps->n].cls = c;
    ps->p[ps->n].cnt = k;
    ps->n++;
}

static struct pairs* extras_target; /* the block_extras callback's destination */
static uint32_t* extras_at;         /* and the class each instruction gets, or UINT32_MAX */

static void add_extra(const char* key, size_t at) {
    const uint32_t c = cls_intern(key);
    pairs_add(extras_target, c, 1);
    extras_at[at] = c;
}

/* Restarts QEMU still owes the watched instruction (at this address) that asked for them.
   A restart may run in another block than the first try (one that starts at the
   instruction: a restore in a delay slot), so it is known by its address. */
static uint64_t pending_vaddr;
static unsigned pending_restarts;
static uint64_t restart_mismatches;

/*
 * A watched instruction runs. When QEMU will stop here for a trap of its own and then
 * restart at this instruction, the block counted (when it was entered) the instructions
 * from here to its end, which do not run now: they run in the block QEMU starts at this
 * instruction after the trap. Take them back, once per restart, from the current phase
 * (the counts are unsigned: the block's executions, added at the next flush, make it up).
 * The restarts themselves run this callback again; they are not new executions.
 */
static void vcpu_insn_event(unsigned int vcpu_index, void* userdata) {
    (void)vcpu_index;
    const struct watch* w = userdata;
    if (pending_restarts) {
        if (pending_vaddr == w->vaddr) {
            pending_restarts--;
            return;
        }
        /* the window model and QEMU disagree: count it, and start afresh */
        if (restart_mismatches++ == 0) {
            report(
                "fb89_count: warning: a restart QEMU was expected to make did not come "
                "(the window model is out of step with QEMU)\n");
        }
        pending_restarts = 0;
    }
    const unsigned restarts = isa->on_event(w->event);
    if (!restarts) {
        return;
    }
    const struct block* b = w->b;
    uint64_t* tot = phase_cls[cur_phase];
    for (uint32_t k = w->index; k < b->ninsns; k++) {
        tot[b->insns[k].cls] -= restarts;
        if (k > w->index && b->insns[k].extra != UINT32_MAX) {
            tot[b->insns[k].extra] -= restarts;
        }
        phase_insns[cur_phase] -= restarts;
        phase_bytes[cur_phase] -= (uint64_t)restarts * b->insns[k].bytes;
    }
    ((struct block*)b)->cut += restarts;
    pending_vaddr = w->vaddr;
    pending_restarts = restarts;
}

static void vcpu_tb_trans(qemu_plugin_id_t id, struct qemu_plugin_tb* tb) {
    (void)id;
    size_t n = qemu_plugin_tb_n_insns(tb);
    if (n > 4096) { /* QEMU's blocks hold at most 512 instructions */
        report("fb89_count: a translated block of more than 4096 instructions\n");
        abort();
    }
    /* room for every instruction's class and a pseudo-class at each */
    struct pairs ps = {xmalloc(sizeof(struct pair) * (2 * n + 1)), 0};
    struct fb89_insn* insns = xmalloc(sizeof(struct fb89_insn) * (n + 1));
    struct insn_record* records = xmalloc(sizeof(struct insn_record) * (n + 1));
    struct watch** watches = xmalloc(sizeof(struct watch*) * (n + 1));
    size_t nwatches = 0;
    uint64_t bytes = 0;
    char key[KEY_MAX];

    /* the send marks' own code: translated, run, never counted */
    if (n && marks_hi > marks_lo) {
        uint64_t at = qemu_plugin_insn_vaddr(qemu_plugin_tb_get_insn(tb, 0));
        if (at >= marks_lo && at < marks_hi) {
            n = 0;
        }
    }
    for (size_t i = 0; i < n; i++) {
        struct qemu_plugin_insn* qi = qemu_plugin_tb_get_insn(tb, i);
        struct fb89_insn* in = &insns[i];
        in->bytes = qemu_plugin_insn_data(qi);
        in->size = qemu_plugin_insn_size(qi);
        in->vaddr = qemu_plugin_insn_vaddr(qi);
        in->disas = qemu_plugin_insn_disas(qi);
        isa->make_key(in, key);
        if (dump_fp) {
            fprintf(dump_fp, "%08" PRIx64 "\t%s\t%s\n", in->vaddr, key, in->disas ? in->disas : "");
        }
        bytes += in->size;
        records[i].cls = cls_intern(key);
        records[i].extra = UINT32_MAX;
        records[i].bytes = (uint32_t)in->size;
        pairs_add(&ps, records[i].cls, 1);
        if (ncaches) {
            qemu_plugin_register_vcpu_mem_cb(qi, vcpu_mem, QEMU_PLUGIN_CB_NO_REGS,
                                             QEMU_PLUGIN_MEM_RW, NULL);
        }
        if (isa->exec_event) {
            int event = isa->exec_event(in);
            if (event) {
                struct watch* w = xmalloc(sizeof(struct watch));
                w->b = NULL;
                w->vaddr = in->vaddr;
                w->index = (uint32_t)i;
                w->event = event;
                watches[nwatches++] = w;
                qemu_plugin_register_vcpu_insn_exec_cb(qi, vcpu_insn_event, QEMU_PLUGIN_CB_NO_REGS,
                                                       w);
            }
        }
    }
    if (isa->block_extras) {
        uint32_t* at = xmalloc(sizeof(uint32_t) * (n + 1));
        for (size_t i = 0; i < n; i++) {
            at[i] = UINT32_MAX;
        }
        extras_target = &ps;
        extras_at = at;
        isa->block_extras(insns, n, add_extra);
        for (size_t i = 0; i < n; i++) {
            records[i].extra = at[i];
        }
        free(at);
    }
    uint64_t annul = n && isa->annulling_branch ? isa->annulling_branch(&insns[n - 1]) : 0;
    for (size_t i = 0; i < n; i++) {
        free((void*)insns[i].disas);
    }

    struct block* b = xmalloc(sizeof(struct block) + sizeof(struct pair) * ps.n);
    b->exec = 0;
    b->vaddr = n ? insns[0].vaddr : 0;
    b->annul = annul;
    b->cut = 0;
    b->insns = NULL;
    b->ninsns = (uint32_t)n;
    b->bytes = (uint32_t)bytes;
    b->npairs = ps.n;
    memcpy(b->p, ps.p, sizeof(struct pair) * ps.n);
    if (nwatches) {
        b->insns = records;
        records = NULL;
        for (size_t k = 0; k < nwatches; k++) {
            watches[k]->b = b;
        }
    }
    free(records);
    free(watches);
    free(ps.p);
    free(insns);
    if (nblocks == blocks_cap) {
        blocks_cap = blocks_cap ? blocks_cap * 2 : 4096;
        blocks = xrealloc(blocks, sizeof(*blocks) * blocks_cap);
    }
    blocks[nblocks++] = b;
    blocks_translated++;

    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &b->exec, 1);
}

/*
 * Delay slots annulled since the last flush. A block that ends in an annulling
 * conditional branch at A ran e times; the branch was taken as often as a block starting
 * at its delay slot A + 4 ran (QEMU starts a block there for the taken path only), so
 * the slot was annulled e - taken times. A branch-always with annul never runs its slot.
 */
struct annul_entry {
    uint64_t addr, branch, taken;
};

static uint64_t annulled_slots(void) {
    size_t cap = 64;
    size_t count = 0;
    for (size_t i = 0; i < nblocks; i++) {
        count += blocks[i]->exec && blocks[i]->annul;
    }
    if (!count) {
        return 0;
    }
    while (cap < 2 * count) {
        cap *= 2;
    }
    struct annul_entry* t = xmalloc(sizeof(*t) * cap);
    memset(t, 0, sizeof(*t) * cap);
    for (size_t i = 0; i < nblocks; i++) {
        struct block* b = blocks[i];
        if (!b->exec || !b->annul) {
            continue;
        }
        size_t s = (size_t)(b->annul >> 2) & (cap - 1);
        while (t[s].addr && t[s].addr != b->annul) {
            s = (s + 1) & (cap - 1);
        }
        t[s].addr = b->annul;
        t[s].branch += b->exec - (b->cut < b->exec ? b->cut : b->exec);
    }
    for (size_t i = 0; i < nblocks; i++) {
        struct block* b = blocks[i];
        if (!b->exec || b->vaddr < 4) {
            continue;
        }
        uint64_t a = b->vaddr - 4;
        size_t s = (size_t)(a >> 2) & (cap - 1);
        while (t[s].addr && t[s].addr != a) {
            s = (s + 1) & (cap - 1);
        }
        if (t[s].addr == a) {
            t[s].taken += b->exec;
        }
    }
    uint64_t annulled = 0;
    for (size_t s = 0; s < cap; s++) {
        if (t[s].addr && t[s].branch > t[s].taken) {
            annulled += t[s].branch - t[s].taken;
        }
    }
    free(t);
    return annulled;
}

static void add_to_phase(const char* key, uint64_t k) {
    if (k) {
        phase_cls[cur_phase][cls_intern(key)] += k;
    }
}

/* Multiply out all block counters into the current phase; zero them. */
static void flush_counts(void) {
    if (isa->annulling_branch) {
        uint64_t annulled = annulled_slots();
        if (annulled) {
            phase_cls[cur_phase][annulled_cls] += annulled;
        }
    }
    if (isa->flush_events) {
        isa->flush_events(add_to_phase);
    }
    for (unsigned i = 0; i < ncaches; i++) {
        add_to_phase(caches[i].read_key, caches[i].read_miss);
        add_to_phase(caches[i].write_key, caches[i].write_miss);
        add_to_phase(caches[i].writeback_key, caches[i].writeback);
        caches[i].read_miss = caches[i].write_miss = caches[i].writeback = 0;
    }
    uint64_t* tot = phase_cls[cur_phase];
    uint64_t insns = 0, bytes = 0;
    for (size_t i = 0; i < nblocks; i++) {
        struct block* b = blocks[i];
        uint64_t e = b->exec;
        if (!e) {
            continue;
        }
        b->exec = 0;
        b->cut = 0;
        insns += e * b->ninsns;
        bytes += e * b->bytes;
        for (uint32_t j = 0; j < b->npairs; j++) {
            tot[b->p[j].cls] += e * b->p[j].cnt;
        }
    }
    phase_insns[cur_phase] += insns;
    phase_bytes[cur_phase] += bytes;
}

/* The current phase's counts now: where the next send record's counts start. */
static void send_rebase(void) {
    if (cls_n) {
        memcpy(send_base, phase_cls[cur_phase], sizeof(uint64_t) * cls_n);
    }
    send_base_insns = phase_insns[cur_phase];
}

/* A send record: what the current phase has run since the last (counts flushed). */
static void send_mark(uint64_t commands) {
    if (nsends == sends_cap) {
        sends_cap = sends_cap ? sends_cap * 2 : 256;
        sends = xrealloc(sends, sizeof(*sends) * sends_cap);
    }
    struct send_record* r = &sends[nsends++];
    const uint64_t* now = phase_cls[cur_phase];
    r->phase = cur_phase;
    r->commands = commands;
    r->insns = phase_insns[cur_phase] - send_base_insns;
    r->n = 0;
    for (uint32_t c = 0; c < cls_n; c++) {
        r->n += now[c] != send_base[c];
    }
    r->cls = xmalloc(sizeof(uint32_t) * (r->n ? r->n : 1));
    r->delta = xmalloc(sizeof(uint64_t) * (r->n ? r->n : 1));
    uint32_t k = 0;
    for (uint32_t c = 0; c < cls_n; c++) {
        if (now[c] != send_base[c]) {
            r->cls[k] = c;
            r->delta[k++] = now[c] - send_base[c];
        }
    }
    send_rebase();
}

static void vcpu_syscall(qemu_plugin_id_t id, unsigned int vcpu_index, int64_t num, uint64_t a1,
                         uint64_t a2, uint64_t a3, uint64_t a4, uint64_t a5, uint64_t a6,
                         uint64_t a7, uint64_t a8) {
    (void)id;
    (void)a4;
    (void)a5;
    (void)a6;
    (void)a7;
    (void)a8;
    if (vcpu_index != 0 && !multi_vcpu) {
        multi_vcpu = true;
        report(
            "fb89_count: warning: guest uses more than one "
            "vCPU/thread; counts are not reliable\n");
    }
    if (num == FB89_SEND_SYSCALL) {
        flush_counts();
        send_mark((uint32_t)a1);
        return;
    }
    if (num != FB89_MARKER_SYSCALL) {
        return;
    }
    /* the guest names its send marks' code; both guests are 32-bit, and QEMU may hand
       over an address with the top bit set sign-extended */
    if ((uint32_t)a3 > (uint32_t)a2) {
        marks_lo = (uint32_t)a2;
        marks_hi = (uint32_t)a3;
    }
    if (a1 >= FB89_NPHASES) {
        if (bad_markers++ == 0) {
            report(
                "fb89_count: warning: marker phase out of range "
                "0..15, ignored\n");
        }
        return;
    }
    flush_counts();
    cur_phase = (unsigned)a1;
    phase_entered[cur_phase]++;
    send_rebase();
    if (phase_fp) {
        /* the phase so far, for whoever must say where a guest that dies stopped */
        rewind(phase_fp);
        fprintf(phase_fp, "%u\n", cur_phase);
        fflush(phase_fp);
    }
}

/* ---- output --------------------------------------------------------------- */

static void put_json_string(FILE* f, const char* s) {
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

static int cmp_key_ids(const void* a, const void* b) {
    uint32_t x = *(const uint32_t*)a, y = *(const uint32_t*)b;
    return strcmp(cls_keys[x], cls_keys[y]);
}

static void plugin_exit(qemu_plugin_id_t id, void* userdata) {
    (void)id;
    (void)userdata;
    if (getpid() != install_pid) {
        return; /* forked child of the guest: only the original writes */
    }
    flush_counts();
    if (dump_fp) {
        fclose(dump_fp);
        dump_fp = NULL;
    }

    FILE* f = fopen(out_path, "w");
    if (!f) {
        char msg[512];
        snprintf(msg, sizeof(msg), "fb89_count: cannot open %s for writing\n", out_path);
        report(msg);
        return;
    }
    uint32_t* order = xmalloc(sizeof(uint32_t) * (cls_n ? cls_n : 1));
    for (uint32_t i = 0; i < cls_n; i++) {
        order[i] = i;
    }
    qsort(order, cls_n, sizeof(uint32_t), cmp_key_ids);

    uint64_t total = 0;
    for (int p = 0; p < FB89_NPHASES; p++) {
        total += phase_insns[p];
    }
    fprintf(f,
            "{\"tool\":\"fb89_count\",\"version\":1,\"isa\":\"%s\","
            "\"guest_instructions\":%" PRIu64
            ","
            "\"blocks_translated\":%" PRIu64
            ","
            "\"multi_vcpu\":%s,\"bad_markers\":%" PRIu64
            ","
            "\"restart_mismatches\":%" PRIu64
            ",\n"
            " \"phases\":[",
            isa->name, total, blocks_translated, multi_vcpu ? "true" : "false", bad_markers,
            restart_mismatches);
    bool firstp = true;
    for (int p = 0; p < FB89_NPHASES; p++) {
        if (phase_insns[p] == 0 && phase_entered[p] == 0) {
            continue;
        }
        fprintf(f,
                "%s\n  {\"phase\":%d,\"entered\":%" PRIu64 ",\"instructions\":%" PRIu64
                ",\"bytes\":%" PRIu64 ",\"classes\":{",
                firstp ? "" : ",", p, phase_entered[p], phase_insns[p], phase_bytes[p]);
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
    fputs("\n ],\n \"sends\":[", f);
    for (size_t i = 0; i < nsends; i++) {
        const struct send_record* r = &sends[i];
        fprintf(f,
                "%s\n  {\"phase\":%u,\"commands\":%" PRIu64 ",\"instructions\":%" PRIu64
                ",\"classes\":{",
                i ? "," : "", r->phase, r->commands, r->insns);
        for (uint32_t k = 0; k < r->n; k++) {
            fputs(k ? "," : "", f);
            put_json_string(f, cls_keys[r->cls[k]]);
            fprintf(f, ":%" PRIu64, r->delta[k]);
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

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t* info, int argc,
                                           char** argv) {
    const char* dump_path = NULL;

    isa = NULL;
    char known[256] = "";
    for (const struct fb89_isa* const* k = fb89_isas; *k && !isa; k++) {
        for (const char* const* t = (*k)->qemu_targets; *t; t++) {
            if (info && info->target_name && strcmp(info->target_name, *t) == 0) {
                isa = *k;
            }
            snprintf(known + strlen(known), sizeof(known) - strlen(known), "%s%s",
                     known[0] ? ", " : "", *t);
        }
    }
    if (!isa) {
        char msg[512];
        snprintf(msg, sizeof(msg),
                 "fb89_count: no instruction set of ours for QEMU target '%s' (known: %s)\n",
                 info && info->target_name ? info->target_name : "?", known);
        report(msg);
        return 1;
    }

    for (int i = 0; i < argc; i++) {
        const char* a = argv[i];
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
        } else if (strncmp(a, "cache=", 6) == 0) {
            if (!cache_option(a)) {
                char msg[256];
                snprintf(msg, sizeof(msg),
                         "fb89_count: bad '%s' (expected cache=SIZE:LINE:wb "
                         "or :wt, powers of two, at most %d caches)\n",
                         a, FB89_MAX_CACHES);
                report(msg);
                return 1;
            }
        } else if (!isa->option || !isa->option(a)) {
            char msg[512];
            snprintf(msg, sizeof(msg),
                     "fb89_count: unknown argument '%s' "
                     "(expected out=PATH [dump=PATH] [phase=PATH] [cache=SIZE:LINE:wb|wt]%s)\n",
                     a, isa->options_help ? isa->options_help : "");
            report(msg);
            return 1;
        }
    }
    if (!out_path) {
        report("fb89_count: missing required argument out=PATH\n");
        return 1;
    }
    if (info && info->system_emulation) {
        report(
            "fb89_count: warning: written for linux-user "
            "(qemu-m68k, qemu-sparc32plus); system emulation is untested\n");
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
    FILE* f = fopen(out_path, "w");
    if (!f) {
        report("fb89_count: cannot open out= file for writing\n");
        return 1;
    }
    fclose(f);

    install_pid = getpid();
    annulled_cls = cls_intern("@annulled_slot");
    cur_phase = 0;
    phase_entered[0] = 1;
    qemu_plugin_register_vcpu_tb_trans_cb(id, vcpu_tb_trans);
    qemu_plugin_register_vcpu_syscall_cb(id, vcpu_syscall);
    qemu_plugin_register_atexit_cb(id, plugin_exit, NULL);
    return 0;
}
