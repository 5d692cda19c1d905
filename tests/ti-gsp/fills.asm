* fb89: FILL, LINE and PIXT in TI's simulator GSPSIM 1.04, the figures controller-validate holds the model to.
* Run it in GSPSIM (TI's 1987 disk in birdybro/TMS34010_Info, under DOSBox): assemble, link at 3F0000h, run to fin, read the clock at each mN; each mN -> mN+1 is one instruction's states, the second pass warm.
PSIZE   .set    0C0000150h
CONTROL .set    0C00000B0h
CONVDP  .set    0C0000140h
PMASK   .set    0C0000160h
SADDR   .set    b0
DADDR   .set    b2
DPTCH   .set    b3
OFFSET  .set    b4
DYDX    .set    b7
COLOR1  .set    b9
COUNT   .set    b10
INC1    .set    b11
INC2    .set    b12
        .global start
        .text
start:  movk    8,a0
        move    a0,@PSIZE
        clr     a0
        move    a0,@CONTROL
        move    a0,@PMASK
        movi    2000h,DPTCH
        movk    18,a0
        move    a0,@CONVDP
        clr     OFFSET
        movi    0FFFFFFFFh,COLOR1
        movk    2,a3
again:
m0:     clr     DADDR
        movi    [1,100],DYDX
m1:     fill    xy
m2:     movi    [2,1],DADDR
        movi    [1,100],DYDX
m3:     fill    xy
m4:     movi    [3,0],DADDR
        movi    [1,1024],DYDX
m5:     fill    xy
m6:     movi    [10,0],DADDR
        movi    [10,100],DYDX
m7:     fill    xy
m8:     movi    [30,0],DADDR
        movi    [1,1],DYDX
m9:     fill    xy
m10:    movi    [40,0],DADDR
        movi    [100,1],DYDX
m11:    fill    xy
m12:    movi    [200,0],DADDR
        movi    [0,100],DYDX
        movi    -100,SADDR
        movi    100,COUNT
        movi    [1,1],INC1
        movi    [0,1],INC2
m13:    line    0
m14:    movi    [5,7],a1
m15:    pixt    a0,*a1.xy
m16:    nop
        dsj     a3,again
        movk    16,a0
        move    a0,@PSIZE
        movi    4000h,DPTCH
        movk    17,a0
        move    a0,@CONVDP
        movk    2,a3
again2:
m17:    clr     DADDR
        movi    [1,100],DYDX
m18:    fill    xy
m19:    movi    [2,1],DADDR
        movi    [1,100],DYDX
m20:    fill    xy
m21:    movi    [3,0],DADDR
        movi    [1,1024],DYDX
m22:    fill    xy
m23:    movi    [10,0],DADDR
        movi    [100,1],DYDX
m24:    fill    xy
m25:    movi    4000h,a1
m26:    pixt    *a1,a2
m27:    movi    [200,0],DADDR
        movi    [0,100],DYDX
        movi    -100,SADDR
        movi    100,COUNT
        movi    [1,1],INC1
        movi    [0,1],INC2
m28:    line    0
m29:    nop
        dsj     a3,again2
fin:    jruc    fin
