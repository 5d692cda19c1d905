/*
 * isa.h - what the counting plugin (count.c) asks of an instruction set. Each
 * instruction set's part lives in its own folder beside the common core, as gem5 keeps
 * src/arch/sparc beside src/arch/x86: period/<isa>/classify.c, defining
 * `const struct fb89_isa fb89_isa_<isa>`. The build links every folder's into the same
 * plugin and lists them in fb89_isas (a file it writes: period/plugin/CMakeLists.txt);
 * count.c picks one by the name QEMU gives its target ("m68k", "sparc32plus", "i386").
 */
#ifndef FB89_PLUGIN_ISA_H
#define FB89_PLUGIN_ISA_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define FB89_KEY_MAX 192

/* One instruction of a block being translated. */
struct fb89_insn {
    const uint8_t* bytes; /* its encoding, as the guest stores it (qemu_plugin_insn_data) */
    size_t size;
    uint64_t vaddr;
    const char* disas; /* QEMU's disassembly, or NULL */
};

/* Adds `n` executions of the pseudo-class `key` (a key starting with '@': an event that
   costs time but is no instruction of the guest's, such as a trap). */
typedef void (*fb89_add_fn)(const char* key, uint64_t n);

struct fb89_isa {
    const char* name;                /* "m68k", "sparc": as fb89's host profiles say */
    const char* const* qemu_targets; /* the target names QEMU reports, NULL-terminated */

    /* Writes the class key of one instruction into key[FB89_KEY_MAX]. */
    void (*make_key)(const struct fb89_insn* insn, char* key);

    /* Optional: pseudo-classes of a block, seen at translation and counted each time the
       block runs (e.g. "@load_use": the instruction at `at` waits for the load before it).
       Calls add(key, at) once for each. */
    void (*block_extras)(const struct fb89_insn* insns, size_t n,
                         void (*add)(const char* key, size_t at));

    /* Optional: the address of the annulling conditional branch that ends a block (its
       delay slot runs only when it is taken), else 0. The core counts the slots annulled
       as "@annulled_slot": the branch's executions less those of the blocks that start at
       its delay slot. */
    uint64_t (*annulling_branch)(const struct fb89_insn* last);

    /* Optional: a non-zero event when `insn` must be watched each time it runs (a callback
       per execution: keep it for rare instructions), and what to do when it runs. on_event
       returns how many times QEMU itself will run the instruction again before it
       completes (QEMU's own window traps restart it): the core then takes back what those
       restarts count twice, and does not hand the restarts to on_event. */
    int (*exec_event)(const struct fb89_insn* insn);
    unsigned (*on_event)(int event);
    /* Optional: hands the counts of pseudo-classes kept by on_event to the current phase
       and zeroes them; called at every phase change and at exit. */
    void (*flush_events)(fb89_add_fn add);

    /* Optional: takes a plugin argument of the instruction set's own ("windows=7");
       returns false if it does not know it. */
    bool (*option)(const char* arg);
    const char* options_help; /* e.g. " [windows=N]" */
};

/* Every instruction set built in, NULL-terminated (written by the build). */
extern const struct fb89_isa* const fb89_isas[];

#endif
