// The TMS34010's opcodes by instruction form, as the data sheet (SPVS002C) and the User's
// Guide's instruction pages encode them: the word of each mnemonic before its registers
// (Rs in bits 8-5, the file in bit 4, Rd in bits 3-0) or constants are put in. Read by the
// assembler (gsp_assembler.cpp); internal to the controller library.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace fb89::controller::gsp {

struct Opcode {
    std::string_view mnemonic;
    uint16_t word;
};

// Rs,Rd
inline constexpr Opcode kRegisterPairOps[] = {
    {"ADD", 0x4000},   {"ADDC", 0x4200},  {"SUB", 0x4400},   {"SUBB", 0x4600},  {"CMP", 0x4800},
    {"AND", 0x5000},   {"ANDN", 0x5200},  {"OR", 0x5400},    {"XOR", 0x5600},   {"DIVS", 0x5800},
    {"DIVU", 0x5A00},  {"MPYS", 0x5C00},  {"MPYU", 0x5E00},  {"LMO", 0x6A00},   {"MODS", 0x6C00},
    {"MODU", 0x6E00},  {"ADDXY", 0xE000}, {"SUBXY", 0xE200}, {"CMPXY", 0xE400}, {"CPW", 0xE600},
    {"CVXYL", 0xE800}, {"MOVX", 0xEC00},  {"MOVY", 0xEE00},  {"DRAV", 0xF600}};
// Rd
inline constexpr Opcode kOneRegisterOps[] = {{"REV", 0x0020},  {"EXGPC", 0x0120}, {"GETPC", 0x0140},
                                             {"JUMP", 0x0160}, {"GETST", 0x0180}, {"PUTST", 0x01A0},
                                             {"ABS", 0x0380},  {"NEG", 0x03A0},   {"NEGB", 0x03C0},
                                             {"NOT", 0x03E0},  {"CALL", 0x0920}};
// no operand
inline constexpr Opcode kPlainOps[] = {{"NOP", 0x0300},   {"CLRC", 0x0320},   {"SETC", 0x0DE0},
                                       {"DINT", 0x0360},  {"EINT", 0x0D60},   {"EMU", 0x0100},
                                       {"POPST", 0x01C0}, {"PUSHST", 0x01E0}, {"RETI", 0x0940}};

// IW,Rd or IL,Rd: the short form's word (0: none), the long form's, and whether the value is
// kept as its ones' complement.
struct ImmediateOpcode {
    std::string_view mnemonic;
    uint16_t short_form, long_form;
    bool complement;
};
inline constexpr ImmediateOpcode kImmediateOps[] = {
    {"MOVI", 0x09C0, 0x09E0, false}, {"ADDI", 0x0B00, 0x0B20, false},
    {"CMPI", 0x0B40, 0x0B60, true},  {"SUBI", 0x0BE0, 0x0D00, true},
    {"ANDI", 0, 0x0B80, true},       {"ORI", 0, 0x0BA0, false},
    {"XORI", 0, 0x0BC0, false}};

// JRcc's condition codes (bits 11-8), with their other names ("" is UC).
struct Condition {
    std::string_view name;
    int code;
};
inline constexpr Condition kConditionCodes[] = {
    {"UC", 0x0}, {"", 0x0},   {"P", 0x1},  {"LS", 0x2}, {"HI", 0x3}, {"LT", 0x4}, {"GE", 0x5},
    {"LE", 0x6}, {"GT", 0x7}, {"C", 0x8},  {"LO", 0x8}, {"B", 0x8},  {"NC", 0x9}, {"HS", 0x9},
    {"NB", 0x9}, {"EQ", 0xA}, {"Z", 0xA},  {"NE", 0xB}, {"NZ", 0xB}, {"V", 0xC},  {"NV", 0xD},
    {"N", 0xE},  {"MI", 0xE}, {"NN", 0xF}, {"PL", 0xF}};

// The row of `table` named `name`, or nullptr.
template <typename Row>
const Row* row_named(std::span<const Row> table, std::string_view name) {
    for (const Row& r : table)
        if (r.mnemonic == name) return &r;
    return nullptr;
}

}  // namespace fb89::controller::gsp
