* fb89: the memory MOVE and PIXT forms the executive runs, in TI's simulator GSPSIM 1.04: each
* alone, after a queued write of 16 or 32 bits, and before a read. Each block runs twice (its
* DSJ loop), the second pass warm; mN -> mN+1 is the block's states, up to its DSJ's fetch.
* tests/controller_sim/gsp_cpu_test.cpp holds the emulator to the warm figures
* (GspCpu.MemoryAccessesTakeTheStatesOfTisSimulator); docs/COST_MODEL.md, "Against TI's
* simulator". Run it with TI's tools: gsp-cycles moves.asm (see the project's notes).
PSIZE   .set    0C0000150h
        .global start
        .text
start:  movk    8,a0
        move    a0,@PSIZE
        setf    16,0,0
        setf    32,0,1
        movi    100000h,a5
        movk    8,a2
        movk    2,a3
l0:     movi    100000h,a1
m0:     move    *a1,a2,0
        nop
m1:     dsj     a3,l0
        movk    2,a3
l1:     movi    100000h,a1
m2:     move    *a1,a2,1
        nop
m3:     dsj     a3,l1
        movk    2,a3
l2:     movi    100000h,a1
m4:     move    *a1+,a2,0
        nop
m5:     dsj     a3,l2
        movk    2,a3
l3:     movi    100000h,a1
m6:     move    *a1+,a2,1
        nop
m7:     dsj     a3,l3
        movk    2,a3
l4:     movi    100000h,a1
m8:     move    -*a1,a2,0
        nop
m9:     dsj     a3,l4
        movk    2,a3
l5:     movi    100000h,a1
m10:    move    -*a1,a2,1
        nop
m11:    dsj     a3,l5
        movk    2,a3
l6:     movi    100000h,a1
m12:    move    *a1(32),a2,0
        nop
m13:    dsj     a3,l6
        movk    2,a3
l7:     movi    100000h,a1
m14:    move    *a1(32),a2,1
        nop
m15:    dsj     a3,l7
        movk    2,a3
l8:     movi    100000h,a1
m16:    move    @100040h,a2,0
        nop
m17:    dsj     a3,l8
        movk    2,a3
l9:     movi    100000h,a1
m18:    move    @100040h,a2,1
        nop
m19:    dsj     a3,l9
        movk    2,a3
l10:    movi    100000h,a1
m20:    move    *a1(8),a2,0
        nop
m21:    dsj     a3,l10
        movk    2,a3
l11:    movi    100000h,a1
m22:    move    *a1(8),a2,1
        nop
m23:    dsj     a3,l11
        movk    2,a3
l12:    movi    100000h,a1
m24:    move    @PSIZE,a2,0
        nop
m25:    dsj     a3,l12
        movk    2,a3
l13:    movi    100000h,a1
m26:    move    a4,*a5,0
        move    *a1,a2,0
        nop
m27:    dsj     a3,l13
        movk    2,a3
l14:    movi    100000h,a1
m28:    move    a4,*a5,0
        move    *a1,a2,1
        nop
m29:    dsj     a3,l14
        movk    2,a3
l15:    movi    100000h,a1
m30:    move    a4,*a5,0
        move    *a1+,a2,0
        nop
m31:    dsj     a3,l15
        movk    2,a3
l16:    movi    100000h,a1
m32:    move    a4,*a5,0
        move    *a1+,a2,1
        nop
m33:    dsj     a3,l16
        movk    2,a3
l17:    movi    100000h,a1
m34:    move    a4,*a5,0
        move    -*a1,a2,0
        nop
m35:    dsj     a3,l17
        movk    2,a3
l18:    movi    100000h,a1
m36:    move    a4,*a5,0
        move    -*a1,a2,1
        nop
m37:    dsj     a3,l18
        movk    2,a3
l19:    movi    100000h,a1
m38:    move    a4,*a5,0
        move    *a1(32),a2,0
        nop
m39:    dsj     a3,l19
        movk    2,a3
l20:    movi    100000h,a1
m40:    move    a4,*a5,0
        move    *a1(32),a2,1
        nop
m41:    dsj     a3,l20
        movk    2,a3
l21:    movi    100000h,a1
m42:    move    a4,*a5,0
        move    @100040h,a2,0
        nop
m43:    dsj     a3,l21
        movk    2,a3
l22:    movi    100000h,a1
m44:    move    a4,*a5,0
        move    @100040h,a2,1
        nop
m45:    dsj     a3,l22
        movk    2,a3
l23:    movi    100000h,a1
m46:    move    a4,*a5,0
        move    *a1(8),a2,0
        nop
m47:    dsj     a3,l23
        movk    2,a3
l24:    movi    100000h,a1
m48:    move    a4,*a5,0
        move    *a1(8),a2,1
        nop
m49:    dsj     a3,l24
        movk    2,a3
l25:    movi    100000h,a1
m50:    move    a4,*a5,0
        move    @PSIZE,a2,0
        nop
m51:    dsj     a3,l25
        movk    2,a3
l26:    movi    100000h,a1
m52:    move    a4,*a5,1
        move    *a1,a2,0
        nop
m53:    dsj     a3,l26
        movk    2,a3
l27:    movi    100000h,a1
m54:    move    a4,*a5,1
        move    *a1,a2,1
        nop
m55:    dsj     a3,l27
        movk    2,a3
l28:    movi    100000h,a1
m56:    move    a4,*a5,1
        move    *a1+,a2,0
        nop
m57:    dsj     a3,l28
        movk    2,a3
l29:    movi    100000h,a1
m58:    move    a4,*a5,1
        move    *a1+,a2,1
        nop
m59:    dsj     a3,l29
        movk    2,a3
l30:    movi    100000h,a1
m60:    move    a2,*a1,0
        nop
        nop
        nop
        nop
        nop
        nop
m61:    dsj     a3,l30
        movk    2,a3
l31:    movi    100000h,a1
m62:    move    a2,*a1,1
        nop
        nop
        nop
        nop
        nop
        nop
m63:    dsj     a3,l31
        movk    2,a3
l32:    movi    100000h,a1
m64:    move    a2,*a1+,0
        nop
        nop
        nop
        nop
        nop
        nop
m65:    dsj     a3,l32
        movk    2,a3
l33:    movi    100000h,a1
m66:    move    a2,*a1+,1
        nop
        nop
        nop
        nop
        nop
        nop
m67:    dsj     a3,l33
        movk    2,a3
l34:    movi    100000h,a1
m68:    move    a2,-*a1,0
        nop
        nop
        nop
        nop
        nop
        nop
m69:    dsj     a3,l34
        movk    2,a3
l35:    movi    100000h,a1
m70:    move    a2,-*a1,1
        nop
        nop
        nop
        nop
        nop
        nop
m71:    dsj     a3,l35
        movk    2,a3
l36:    movi    100000h,a1
m72:    move    a2,*a1(32),0
        nop
        nop
        nop
        nop
        nop
        nop
m73:    dsj     a3,l36
        movk    2,a3
l37:    movi    100000h,a1
m74:    move    a2,*a1(32),1
        nop
        nop
        nop
        nop
        nop
        nop
m75:    dsj     a3,l37
        movk    2,a3
l38:    movi    100000h,a1
m76:    move    a2,@100080h,0
        nop
        nop
        nop
        nop
        nop
        nop
m77:    dsj     a3,l38
        movk    2,a3
l39:    movi    100000h,a1
m78:    move    a2,@100080h,1
        nop
        nop
        nop
        nop
        nop
        nop
m79:    dsj     a3,l39
        movk    2,a3
l40:    movi    100000h,a1
m80:    move    a2,@PSIZE,0
        nop
        nop
        nop
        nop
        nop
        nop
m81:    dsj     a3,l40
        movk    2,a3
l41:    movi    100000h,a1
m82:    move    a2,*a1,0
        move    *a5,a4,0
        nop
m83:    dsj     a3,l41
        movk    2,a3
l42:    movi    100000h,a1
m84:    move    a2,*a1,1
        move    *a5,a4,0
        nop
m85:    dsj     a3,l42
        movk    2,a3
l43:    movi    100000h,a1
m86:    move    a2,*a1+,0
        move    *a5,a4,0
        nop
m87:    dsj     a3,l43
        movk    2,a3
l44:    movi    100000h,a1
m88:    move    a2,*a1+,1
        move    *a5,a4,0
        nop
m89:    dsj     a3,l44
        movk    2,a3
l45:    movi    100000h,a1
m90:    move    a2,-*a1,0
        move    *a5,a4,0
        nop
m91:    dsj     a3,l45
        movk    2,a3
l46:    movi    100000h,a1
m92:    move    a2,-*a1,1
        move    *a5,a4,0
        nop
m93:    dsj     a3,l46
        movk    2,a3
l47:    movi    100000h,a1
m94:    move    a2,*a1(32),0
        move    *a5,a4,0
        nop
m95:    dsj     a3,l47
        movk    2,a3
l48:    movi    100000h,a1
m96:    move    a2,*a1(32),1
        move    *a5,a4,0
        nop
m97:    dsj     a3,l48
        movk    2,a3
l49:    movi    100000h,a1
m98:    move    a2,@100080h,0
        move    *a5,a4,0
        nop
m99:    dsj     a3,l49
        movk    2,a3
l50:    movi    100000h,a1
m100:   move    a2,@100080h,1
        move    *a5,a4,0
        nop
m101:   dsj     a3,l50
        movk    2,a3
l51:    movi    100000h,a1
m102:   move    a2,@PSIZE,0
        move    *a5,a4,0
        nop
m103:   dsj     a3,l51
        movk    2,a3
l52:    movi    100000h,a1
m104:   move    a4,*a5,0
        move    a2,*a1,0
        move    *a5,a4,0
        nop
m105:   dsj     a3,l52
        movk    2,a3
l53:    movi    100000h,a1
m106:   move    a4,*a5,0
        move    a2,*a1,1
        move    *a5,a4,0
        nop
m107:   dsj     a3,l53
        movk    2,a3
l54:    movi    100000h,a1
m108:   move    a4,*a5,0
        move    a2,*a1+,0
        move    *a5,a4,0
        nop
m109:   dsj     a3,l54
        movk    2,a3
l55:    movi    100000h,a1
m110:   move    a4,*a5,0
        move    a2,*a1+,1
        move    *a5,a4,0
        nop
m111:   dsj     a3,l55
        movk    2,a3
l56:    movi    100000h,a1
m112:   move    a4,*a5,0
        move    a2,-*a1,0
        move    *a5,a4,0
        nop
m113:   dsj     a3,l56
        movk    2,a3
l57:    movi    100000h,a1
m114:   move    a4,*a5,0
        move    a2,-*a1,1
        move    *a5,a4,0
        nop
m115:   dsj     a3,l57
        movk    2,a3
l58:    movi    100000h,a1
m116:   move    a4,*a5,0
        move    a2,*a1(32),0
        move    *a5,a4,0
        nop
m117:   dsj     a3,l58
        movk    2,a3
l59:    movi    100000h,a1
m118:   move    a4,*a5,0
        move    a2,*a1(32),1
        move    *a5,a4,0
        nop
m119:   dsj     a3,l59
        movk    2,a3
l60:    movi    100000h,a1
m120:   move    a4,*a5,0
        move    a2,@100080h,0
        move    *a5,a4,0
        nop
m121:   dsj     a3,l60
        movk    2,a3
l61:    movi    100000h,a1
m122:   move    a4,*a5,0
        move    a2,@100080h,1
        move    *a5,a4,0
        nop
m123:   dsj     a3,l61
        movk    2,a3
l62:    movi    100000h,a1
m124:   move    a4,*a5,0
        move    a2,@PSIZE,0
        move    *a5,a4,0
        nop
m125:   dsj     a3,l62
* PIXT at 8 bits a pixel, then at 16
        movk    8,a0
        move    a0,@PSIZE
        movk    2,a3
l63:    movi    100000h,a1
m126:   pixt    a2,*a1
        nop
        nop
        nop
        nop
        nop
        nop
m127:   dsj     a3,l63
        movk    2,a3
l64:    movi    100000h,a1
m128:   pixt    a2,*a1
        move    *a5,a4,0
        nop
m129:   dsj     a3,l64
        movk    2,a3
l65:    movi    100000h,a1
m130:   move    a4,*a5,0
        pixt    a2,*a1
        move    *a5,a4,0
        nop
m131:   dsj     a3,l65
        movk    2,a3
l66:    movi    100000h,a1
m132:   pixt    *a1,a2
        nop
m133:   dsj     a3,l66
        movk    2,a3
l67:    movi    100000h,a1
m134:   move    a4,*a5,0
        pixt    *a1,a2
        nop
m135:   dsj     a3,l67
        movk    2,a3
l68:    movi    100000h,a1
m136:   pixt    *a1,a2
        pixt    a2,*a1
        nop
        nop
        nop
        nop
        nop
        nop
m137:   dsj     a3,l68
        movk    16,a0
        move    a0,@PSIZE
        movk    2,a3
l69:    movi    100000h,a1
m138:   pixt    a2,*a1
        nop
        nop
        nop
        nop
        nop
        nop
m139:   dsj     a3,l69
        movk    2,a3
l70:    movi    100000h,a1
m140:   pixt    a2,*a1
        move    *a5,a4,0
        nop
m141:   dsj     a3,l70
        movk    2,a3
l71:    movi    100000h,a1
m142:   move    a4,*a5,0
        pixt    a2,*a1
        move    *a5,a4,0
        nop
m143:   dsj     a3,l71
        movk    2,a3
l72:    movi    100000h,a1
m144:   pixt    *a1,a2
        nop
m145:   dsj     a3,l72
        movk    2,a3
l73:    movi    100000h,a1
m146:   move    a4,*a5,0
        pixt    *a1,a2
        nop
m147:   dsj     a3,l73
        movk    2,a3
l74:    movi    100000h,a1
m148:   pixt    *a1,a2
        pixt    a2,*a1
        nop
        nop
        nop
        nop
        nop
        nop
m149:   dsj     a3,l74
fin:    jruc    fin
