/*
 * classify.c - the counting plugin's part for the 386 + 387 (period/plugin/isa.h): keys from
 * QEMU's disassembly, the mnemonic alone for now (the classifier proper replaces this).
 */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "period/plugin/isa.h"

static void make_key(const struct fb89_insn *insn, char *key)
{
    const char *d = insn->disas ? insn->disas : "?";
    size_t n = 0;
    while (d[n] && !isspace((unsigned char)d[n]) && n + 1 < FB89_KEY_MAX) {
        key[n] = d[n];
        n++;
    }
    key[n] = 0;
}

static const char *const targets[] = {"i386", NULL};

const struct fb89_isa fb89_isa_x86 = {
    .name = "x86",
    .qemu_targets = targets,
    .make_key = make_key,
};
