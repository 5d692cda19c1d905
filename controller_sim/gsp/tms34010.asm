; The command executive fb89's controller runs on a TMS34010: read the next command from
; the ring the host writes into the GSP's memory, dispatch on its opcode, load its operands
; into the B file and run FILL or LINE, and look for the next.
;
; This listing is what the controller's per-command cycles are counted from
; (controller_sim/gsp_listing.h): every instruction is priced from the data sheet's
; minimum-cycle tables (SPVS002C pp. 11-14), a memory access by GSPSIM's states around the
; cycles its field needs (p. 19: two states a cycle, plus wait states); `fb89 controller-validate
; --listing` prints it with each line's cycles and source. The counted paths are named
; by the ";@path" lines; a conditional jump on a path says in its comment which way the
; path goes ("taken" or "not taken"). A path ends where it jumps back to `next` (the
; handlers) or dispatches (the loop). TI's own assembler (GSPA 2.00, 1987) assembles it
; with no error and no warning, with the B file's names set as TI's sources set them
; (SADDR = B0 ... PATTRN = B13).
;
; The handlers follow TI's own practice for this chip, as TI's TMS340 Graphics Library
; (TIGA r2.01, 1990) and its port to TI's TIGA development board program it; each handler
; names the file it follows (docs/COST_MODEL.md, "TI's practice"). Read for facts; the code
; is fb89's.
;
; The board is TI's TIGA development board (TDB10/README.1ST): a TMS34010 at INCLK 50.35
; MHz, 1 MB of VRAM in two banks of 256K x 4 parts, all of it the frame buffer from
; VRAM_START, and DRAM from address 0 for the program, the ring and data (TDB10/OEMPRIMS/
; CLEARFRM.ASM). A VRAM row, the same row of every part of both banks, is 16,384 bits:
; two lines of the 1024 x 780 x 8 frame, whose 390 rows fill 780 of the VRAM's 1,024 lines.
; The depth buffer (1.6 MB at 16 bits) lies in DRAM at ZBASE: it cannot be in VRAM (the
; frame leaves 244 KB of it), and the TDB's 1 MB of DRAM is too small for it, so fb89's
; board is the TDB with 4 MB of DRAM in the same place.
;
; Set once at start-up, outside the counted paths: field 0 is 16 bits and field 1 32 bits
; (SETF 16,0,0 and SETF 32,0,1), PSIZE and DPTCH for the frame (FPSHIFT: log2 of DPTCH),
; OFFSET = VRAM_START, the window to the frame with clipping on (CONTROL's W = 3), and the
; registers below.
;   A0  the ring's read pointer (a bit address)     A1  the host's write pointer, last read
;   A2  the ring's end                              A3  the ring's start
;   A4  the dispatch table                          A5-A9  scratch
; and in the depth commands' pixel loop
;   A8  the depth word's address    A10 the pixel's address    A11 Z    A12 Z's step
;   A13 the pixels left             A14 the colour word        A7  where the loop returns
; The depth buffer (ZBASE) is a row of 2^ZPITCH bits a row, the board's depth word wide
; (ZSHIFT = 0 for 16 bits, 1 for 32), set with it at start-up; the window (WSTART, WEND) is
; the frame.
;
; The host writes each command as 16-bit words (docs/COST_MODEL.md, "Modelled bytes"):
;   FRAME_BEGIN  opcode, frame, width, height, background
;   FILL_RECT    opcode, x, y, w, h, colour
;   DRAW_SPAN    opcode, x0, y, x1, colour
;   FRAME_END    opcode
;   DEPTH_CLEAR  opcode
;   DEPTH_SPAN   opcode, x0, y, x1, z (2 words), dz (2 words), colour
;   FACE         opcode, count, colour, x_ref, y_ref, z (2), dzdx (2), dzdy (2), then each
;                point's x (2 words) and y (2 words), in 1/256 pixel
; x before y, so that one 32-bit field read makes an XY address (X in the low half).
; A colour word holds the pixel repeated to 16 bits.

HOST_WP   .equ  00010000h        ; where the host writes its write pointer
FRAME_NO  .equ  00010020h        ; the frame being drawn, for the host to read
HSTCTLL   .equ  0C00000F0h       ; host control, low byte: the message to the host
MSG_FRAME .equ  0010h            ; MSGOUT = 1: a frame is done
PSIZE     .equ  0C0000150h       ; the pixel size
ZBASE     .equ  00400000h        ; the depth buffer, in DRAM
VRAM_START .equ 010000000h       ; the frame buffer: the TDB's VRAM (CLEARFRM.ASM)
DPYCTL    .equ  0C0000080h       ; display control: ENV, SRE, SRT (TI's GSPREG.INC)
FPSHIFT   .equ  00010140h        ; log2 of the frame's pitch in bits (13: 1,024 pixels of 8)
ENV_DSTBM .equ  00010160h        ; TIGA's environment: the destination bit-map (TIGA_CALL)
ENV_ORIGIN .equ 00010180h        ; and the viewport's origin
ZSHIFT    .equ  00010040h        ; the depth word: 0 for 16 bits, 1 for 32
ZPITCH    .equ  00010060h        ; log2 of the depth buffer's row, in bits
FACE_REF  .equ  00010080h        ; a FACE's reference pixel, y:x
FACE_Z    .equ  000100A0h        ; its Z at the current row's reference column
FACE_DZDY .equ  000100C0h        ; its Z step a row
FACE_PTS  .equ  00010120h        ; its first point, in the ring
EDGES     .equ  00011000h        ; its edges, 4 longs each: ny, N0 (2), nx

;@path COMMON next
;@path FRAME_BEGIN frame_begin
;@path FRAME_BEGIN:fill frame_begin_fill
;@path FRAME_BEGIN:large frame_begin take fb_fill
;@path FILL_RECT fill_rect
;@path DRAW_SPAN:line span_line
;@path DRAW_SPAN:fill span_fill
;@path FRAME_END frame_end
;@path DEPTH_CLEAR depth_clear
;@path DEPTH_SPAN depth_span zloop16
;@path DEPTH_SPAN32 depth_span zloop32 take zloop32
;@path DEPTH_SPAN:cut depth_span zloop16 take zclip
;@path DEPTH_SPAN32:cut depth_span zloop32 take zclip take zloop32
;@path DEPTH_SPAN:outside depth_span take zout
;@path DEPTH_SPAN:below depth_span take zbelow
;@path DEPTH_SPAN:empty depth_span take zempty
;@path DEPTH_SPAN:emptycut depth_span take zclip take zempty
;@path ZPIXEL16:nearer zloop16 zloop16
;@path ZPIXEL16:farther zloop16 zloop16 take zfar16
;@path ZPIXEL32:nearer zloop32 zloop32
;@path ZPIXEL32:farther zloop32 zloop32 take zfar32
;@path ZPIXEL16:last zloop16 zdone take zfar16 fall zloop16
;@path ZPIXEL32:last zloop32 zdone32 take zfar32 fall zloop32
;@path ZSPAN_EXIT zdone
;@path FACE face face_point
;@path FACE:point face_point face_point
;@path FACE:last face_point face_row fall face_b fall face_point
;@path FACE:row face_row face_edge
;@path FACE:edge face_edge face_edge
;@path FACE:lastedge face_edge face_test fall face_edge
;@path FACE:nearer face_edge face_edge fall face_next
;@path FACE:level face_edge face_edge take face_level
;@path FACE:levelnone face_edge face_edge take face_level fall face_next
;@path FACE:far face_edge face_edge take face_far
;@path FACE:farnone face_edge face_edge take face_far fall face_next
;@path FACE:levelpoint face_point face_point fall face_tie fall face_bias
;@path FACE:span face_test zloop16
;@path FACE:span32 face_test zloop32 take zloop32
;@path FACE:step face_step face_row
;@path FACE:empty face_test face_row take face_step
;@path FACE:done face_row take face_done
;@path TIGA_CALL tiga_call

next:     CMP    A1,A0           ; at the host's last known write pointer?
          JRNE   more            ; taken: a command is waiting
          MOVE   @HOST_WP,A1,1   ; (idle: read the host's write pointer until it moves)
          JRUC   next
more:     CMP    A2,A0           ; at the ring's end?
          JRLO   fetch           ; taken: not yet (the host wraps only between commands)
          MOVE   A3,A0           ; (at the end: back to the ring's start)
fetch:    MOVE   *A0+,A5,0       ; the opcode word
          SLL    5,A5            ; times 32 bits: the offset of its entry in the table
          ADD    A4,A5           ; the entry's address
          MOVE   *A5,A5,1        ; the handler's address
          JUMP   A5              ; dispatch

; FRAME_BEGIN clears the frame through the VRAMs' serial registers, as TI's port of its
; library to the development board does (TDB10/OEMPRIMS/CLEARPAG.ASM, clear_page, and
; CLEARFRM.ASM; SPVU027 pp. 3-20 and 6-5): one VRAM row filled with the background as
; 16-bit pixels, one memory-to-register cycle (a pixel read with DPYCTL's SRT set) that
; loads that row into every part's serial register, then one register-to-memory cycle a
; VRAM row (a FILL one pixel wide, SRT still set) for the frame's other rows. The display
; is off meanwhile (ENV and SRE clear, as TI's routines leave them). A frame larger than
; the VRAM is cleared by FILL (FRAME_BEGIN:fill), as is every frame when the profile's
; clear_as is "fill": TI's clear_screen (TDB10/OEMPRIMS/CLEARSCR.ASM), one FILL XY.
frame_begin:
          MOVE   *A0+,A5,0       ; the frame's number
          MOVE   A5,@FRAME_NO,0  ; kept for the host (a write: queued)
          MOVE   *A0+,A6,1       ; height:width, the whole frame
          MOVE   A6,A7
          SUBI   10001h,A7
          MOVE   A7,WEND         ; the window: the frame's last row and column
          MOVE   *A0+,A5,0       ; the background's colour word
          MOVE   A5,A7
          SLL    16,A7
          OR     A7,A5           ; the pixel in all 32 bits
          MOVE   A5,COLOR1
          MOVE   A6,A7
          SRL    16,A7           ; the height
          MOVE   @FPSHIFT,A9,0
          SLL    A9,A7           ; the frame's bits
          ADDI   3FFFh,A7
          SRL    14,A7           ; its VRAM rows, 16,384 bits each
          CMPI   512,A7          ; more than the VRAM's 512?
          JRHI   fb_fill         ; not taken: the frame lies in VRAM
          MOVE   DPTCH,A8        ; the frame's pitch, kept
          MOVE   OFFSET,DADDR    ; the first VRAM row
          MOVI   10400h,A5
          MOVE   A5,DYDX         ; DYDX = 1:1024, a VRAM row of 16-bit pixels
          MOVI   4000h,A5
          MOVE   A5,DPTCH        ; a VRAM row a "line"
          MOVE   @PSIZE,A6,0     ; the frame's pixel size, kept
          MOVK   16,A5
          MOVE   A5,@PSIZE,0     ; 16-bit pixels: every write a whole word
          FILL   L               ; the first row in the background
          MOVE   @DPYCTL,A9,0    ; the display's setting, kept
          MOVE   A9,A5
          ANDI   06FFFh,A5       ; video and the display's own transfers off (ENV, SRE)
          ORI    0800h,A5        ; SRT: a pixel access is a serial-register transfer
          MOVE   A5,@DPYCTL,0
          MOVE   OFFSET,DADDR
          PIXT   *DADDR,B14      ; its read: the memory-to-register cycle
          MOVE   OFFSET,A5
          ADDI   4000h,A5
          MOVE   A5,DADDR        ; the second row
          SUBK   1,A7
          SLL    16,A7
          ADDK   1,A7
          MOVE   A7,DYDX         ; DYDX = rows - 1 : 1
          FILL   L               ; a register-to-memory cycle a row
          MOVE   A9,@DPYCTL,0    ; the display back
          MOVE   A8,DPTCH        ; the frame's pitch and pixel size back
          MOVE   A6,@PSIZE,0
          JRUC   next

frame_begin_fill:
          MOVE   *A0+,A5,0       ; the frame's number
          MOVE   A5,@FRAME_NO,0
          MOVE   *A0+,A6,1       ; height:width
          MOVE   A6,A7
          SUBI   10001h,A7
          MOVE   A7,WEND         ; the window
          MOVE   *A0+,A5,0       ; the background's colour word
          MOVE   A5,A7
          SLL    16,A7
          OR     A7,A5
          MOVE   A5,COLOR1
fb_fill:  MOVE   A6,DYDX         ; the whole frame
          CLR    DADDR           ; from 0:0
          FILL   XY              ; the clear
          JRUC   next

fill_rect:
          MOVE   *A0+,A5,1       ; y:x (a memory field goes to a register of its
          MOVE   A5,DADDR        ; pointer's file, then across: GSPA refuses *A0+,DADDR)
          MOVE   *A0+,A5,1
          MOVE   A5,DYDX         ; h:w
          MOVE   *A0+,A5,0       ; the colour word
          MOVE   A5,A6
          SLL    16,A6
          OR     A6,A5
          MOVE   A5,COLOR1
          FILL   XY
          JRUC   next

; DRAW_SPAN: a horizontal line, which TI's draw_line draws with FILL XY, not LINE
; (EXTPRIMS/DRAWLINE.ASM: a horizontal or vertical line found by CMPXY, DYDX its length + 1
; in x and y by SUBXY and ADDI 010001h); ours are all horizontal and left to right. LINE
; stays the profile's other choice ("span_as": "line", DRAW_SPAN:line).
span_fill:
          MOVE   *A0+,A6,1       ; y:x0
          MOVE   A6,DADDR
          MOVE   *A0+,A7,0       ; x1
          MOVE   A6,A5
          MOVX   A7,A5           ; y:x1
          SUBXY  A6,A5           ; 0:(x1 - x0)
          ADDI   10001h,A5       ; 1:n
          MOVE   A5,DYDX
          MOVE   *A0+,A5,0       ; the colour word
          MOVE   A5,A6
          SLL    16,A6
          OR     A6,A5
          MOVE   A5,COLOR1
          FILL   XY
          JRUC   next

span_line:
          MOVE   *A0+,A6,1       ; y:x0
          MOVE   A6,DADDR
          MOVE   *A0+,A7,0       ; x1
          SLL    16,A6
          SRL    16,A6           ; x0
          SUB    A6,A7
          ADDK   1,A7            ; n = x1 - x0 + 1
          MOVE   A7,COUNT        ; n pixels
          MOVE   A7,DYDX         ; DYDX = 0:n (a = n, b = 0)
          MOVK   1,INC1          ; both steps one pixel along x
          MOVK   1,INC2
          MOVE   A7,SADDR
          NEG    SADDR           ; the decision variable, 2b - a
          MOVE   *A0+,A5,0       ; the colour word
          MOVE   A5,A6
          SLL    16,A6
          OR     A6,A5
          MOVE   A5,COLOR1
          LINE   0
          JRUC   next

frame_end:
          MOVI   MSG_FRAME,A5
          MOVE   A5,@HSTCTLL,0   ; tell the host the frame is done (an I/O register)
          JRUC   next

;--- the depth commands (stream format version 3) ------------------------------------------
; A depth buffer holds Z >> 12 in 16 bits, or Z in 32; it is cleared to all ones, farther
; than any depth. The pixel loops are the 16-bit word's (ZPIXEL16) and the 32-bit word's
; (ZPIXEL32); a path through a loop is one pixel. A set-up's path ends where it reaches its
; loop; where a set-up's branch goes one way for one depth word and the other for the other,
; the path takes the 16-bit word's way (the 32-bit word's is a state cheaper).

depth_clear:
          MOVE   DPTCH,A6        ; the frame's pitch, kept
          MOVE   @ZPITCH,A5,0
          MOVK   1,A8
          SLL    A5,A8           ; the depth buffer's pitch
          MOVE   A8,DPTCH
          MOVE   @PSIZE,A10,0    ; the frame's pixel size, kept
          MOVK   16,A5
          MOVE   A5,@PSIZE,0     ; 16-bit pixels: the words themselves
          MOVE   WEND,A5         ; the frame's last row and column
          ADDI   10001h,A5       ; its height and width
          MOVE   @ZSHIFT,A8,0
          MOVE   A5,A9
          SLL    16,A9
          SRL    16,A9           ; the width
          SLL    A8,A9           ; in 16-bit words
          SRL    16,A5
          SLL    16,A5
          OR     A9,A5
          MOVE   A5,DYDX         ; DYDX = height:words
          MOVI   ZBASE,A5
          MOVE   A5,DADDR        ; from the first word: FILL L, which the window (the
          MOVK   1,A5            ; frame, narrower than a row of 32-bit words) leaves whole
          NEG    A5              ; all ones
          MOVE   A5,COLOR1
          FILL   L               ; the clear
          MOVE   A6,DPTCH        ; the frame's pitch and pixel size back
          MOVE   A10,@PSIZE,0
          JRUC   next

depth_span:
          MOVE   *A0+,A6,1       ; y:x0
          MOVE   *A0+,A9,0       ; x1
          MOVE   *A0+,A11,1      ; Z at x0
          MOVE   *A0+,A12,1      ; its step
          MOVE   *A0+,A14,0      ; the colour word
          MOVI   next,A7         ; where the pixel loop returns
dspan:    MOVE   A6,A10
          SRA    16,A10          ; y
          JRN    zout            ; not taken: a row above the frame is outside
          MOVE   WEND,A5
          SRA    16,A5           ; the frame's last row
          CMP    A5,A10
          JRGT   zbelow          ; not taken: a row below it is outside
          MOVE   WEND,A5
          SLL    16,A5
          SRL    16,A5           ; the frame's last column
          CMP    A5,A9
          JRLE   zright          ; taken: x1 is inside (else it is cut to the last column)
          MOVE   A5,A9
zright:   MOVE   A6,A5
          SLL    16,A5
          SRA    16,A5           ; x0
          JRN    zclip           ; not taken: x0 is inside (DEPTH_SPAN:cut when not)
zleft:    SUB    A5,A9
          JRN    zempty          ; not taken: something is left of the span
zgo:      ADDK   1,A9            ; (a FACE's run joins here: A5 x0, A9 x1 - x0, A6 y:x0)
          MOVE   A9,A13          ; the pixels
          MOVE   A6,A8
          CVXYL  A8,A10          ; the pixel's address
          SRA    16,A8           ; y
          MOVE   @ZPITCH,A9,0
          SLL    A9,A8           ; the row's offset in the depth buffer
          MOVE   @ZSHIFT,A9,0
          ADDK   4,A9            ; log2 of the depth word's bits
          SLL    A9,A5           ; x0's offset in the row
          ADD    A5,A8
          ADDI   ZBASE,A8        ; the depth word's address
          MOVE   @PSIZE,A6,0     ; the pixel's bits: the step to the next
          MOVE   @ZSHIFT,A9,0    ; the depth word (sets Z)
          JRNE   zloop32         ; not taken: a 16-bit word (DEPTH_SPAN32 when taken)
          JRUC   zloop16

zloop16:  MOVE   *A8,A5,0        ; the depth word here
          MOVE   A11,A9
          SRL    12,A9           ; Z's top 16 of its 28 bits
          CMP    A5,A9
          JRHS   zfar16          ; not taken: nearer (taken: as near or farther)
          MOVE   A9,*A8,0        ; the new depth
          PIXT   A14,*A10        ; the pixel
zfar16:   ADDK   16,A8           ; the next depth word
          ADD    A6,A10          ; the next pixel
          ADD    A12,A11         ; Z's step
          DSJ    A13,zloop16     ; taken: more pixels (DSJS: the last is a state dearer)
zdone:    JUMP   A7              ; to the next command, or a FACE's next row

; a FACE's rows (its set-up is below): here, beside the depth loop they run, so that the
; loop, its set-up and the rows share the instruction cache
face_row: MOVE   DADDR,A9        ; the row, y
          MOVE   DYDX,A5
          CMP    A5,A9
          JRGT   face_done       ; not taken: a row to draw
          MOVE   WEND,A12        ; the run so far: the whole row
          SLL    16,A12
          SRL    16,A12          ; to the frame's last column
          CLR    A10             ; from 0
          MOVE   COUNT,A8        ; the edges
          MOVE   PATTRN,A13
          JRUC   face_edge

face_edge:
          MOVE   *A8+,A6,1       ; ny
          MPYS   A9,A6           ; ny y: A6 high, A7 low
          MOVE   *A8+,A5,1
          ADD    A5,A7
          MOVE   *A8+,A5,1
          ADDC   A5,A6           ; N = N0 + ny y
          MOVE   *A8+,A11,1      ; nx (sets N and Z)
          JRZ    face_level      ; not taken: not a level edge (FACE:level when it is)
          JRN    face_right      ; not taken: a left edge (a right one is as dear)
          NOP                    ; (the state that makes the two as dear)
          DIVS   A11,A6          ; N / nx: quotient A6, remainder A7
          JRV    face_far        ; not taken: 32 bits of quotient (FACE:far when not)
          SRA    31,A7
          ADD    A7,A6           ; floor(N / nx)
          NEG    A6              ; the first column the edge covers
          CMP    A6,A10
          JRGE   face_next       ; taken: not a nearer bound (FACE:nearer when it is)
          MOVE   A6,A10
          JRUC   face_next
face_right:
          NEG    A11
          DIVS   A11,A6          ; N / -nx
          JRV    face_far        ; not taken
          SRA    31,A7
          ADD    A7,A6           ; floor(N / -nx): the last column the edge covers
          CMP    A6,A12
          JRLE   face_next       ; taken: not a nearer bound
          MOVE   A6,A12
          JRUC   face_next
face_level:
          MOVE   A6,A6           ; N >= 0: the whole row
          JRNN   face_next       ; taken (FACE:levelnone when not)
          JRUC   face_none
face_far: MOVE   A6,A6           ; (V: the registers kept) N >= 0: no bound
          JRNN   face_next       ; taken (FACE:farnone when not)
face_none:
          CLR    A12             ; N < 0: nothing in this row
          SUBK   1,A12
face_next:
          DSJ    A13,face_edge   ; taken: more edges

face_test:
          CMP    A10,A12
          JRLT   face_step       ; not taken: the run is not empty (FACE:empty when it is)
          MOVE   A12,A9
          SUB    A10,A9          ; x_end - x_begin
          MOVE   COLOR0,A5       ; x_ref: Z at the run's first pixel
          MOVE   A10,A11
          SUB    A5,A11          ; the columns from it
          MOVE   INC2,A12        ; Z's step a column
          MPYS   A12,A11
          MOVE   SADDR,A5        ; Z at the row's reference column
          ADD    A5,A11
          MOVE   DADDR,A6        ; y:x_begin
          SLL    16,A6
          MOVX   A10,A6
          MOVE   COLOR1,A14      ; the colour word
          MOVE   INC1,A7         ; the pixel loop returns to the next row
          MOVE   A10,A5          ; x_begin: the run is in the frame, so the depth
          JRUC   zgo             ; loop's set-up goes on from its window tests

face_step:
          MOVE   DADDR,A9        ; the next row
          ADDK   1,A9
          MOVE   A9,DADDR
          MOVE   SADDR,A11       ; and Z at its reference column
          MOVE   SPTCH,A5
          ADD    A5,A11
          MOVE   A11,SADDR
          JRUC   face_row

face_done:
          JRUC   next


zloop32:  MOVE   *A8,A5,1        ; the depth word here
          CMP    A5,A11
          JRHS   zfar32          ; not taken: nearer (taken: as near or farther)
          MOVE   A11,*A8,1       ; the new depth
          PIXT   A14,*A10        ; the pixel
zfar32:   ADDK   32,A8           ; the next depth word
          ADD    A6,A10          ; the next pixel
          ADD    A12,A11         ; Z's step
          DSJ    A13,zloop32     ; taken: more pixels
zdone32:  JUMP   A7

zclip:    MOVE   A5,A13
          NEG    A13             ; the pixels cut on the left
          MPYS   A12,A13         ; their steps of Z (A13 odd: 32 bits of product)
          ADD    A13,A11         ; Z at column 0
          SRL    16,A6
          SLL    16,A6           ; x0 = 0
          CLR    A5
          JRUC   zleft

zout:     JUMP   A7              ; nothing to draw: above the frame,
zbelow:   JUMP   A7              ; below it,
zempty:   JUMP   A7              ; or nothing left of the span


; FACE, by protocol/coverage.h's rule: each edge from a point to the next has the normal
; nx = ay - by, ny = bx - ax and the edge function's constant k0 = nx(128 - ax) +
; ny(128 - ay), in 64 bits; the set-up keeps N0 = floor((k0 - bias) / 256) (bias 0 for a
; left edge or a level top one, else 1), so that in row y N = N0 + ny y and a left edge
; (nx > 0) covers from column -floor(N / nx), a right one (nx < 0) to floor(N / -nx), and
; a level one all or nothing (N >= 0): the integers row_span's divisions give, from one
; MPYS and one DIVS of 64 by 32 bits an edge a row. A quotient beyond 32 bits (an edge
; all but level, far from the row) bounds nothing or empties the row, by N's sign. The
; row's run goes to the depth loop as a span, Z at its first pixel from the reference.
; Kept in the B file (FACE runs no FILL): the colour word (COLOR1), x_ref (COLOR0), Z's
; step a column (INC2), the edges (PATTRN); in the set-up the points left (COUNT) and the
; lowest and highest y (SADDR, SPTCH); in the rows the row and the last (DADDR, DYDX), Z at
; the row's reference column and its step a row (SADDR, SPTCH), the edge table (COUNT) and
; the pixel loop's return (INC1): the row loop then fits the instruction cache.
face:     MOVE   *A0+,A13,0      ; the point count
          MOVE   A13,PATTRN      ; the edges, for the rows
          MOVE   A13,COUNT       ; and the points, for the set-up
          MOVE   *A0+,A14,0      ; the colour word
          MOVE   A14,COLOR1
          MOVE   *A0+,A6,1       ; y_ref:x_ref
          MOVE   A6,@FACE_REF,1
          MOVE   A6,A5
          SLL    16,A5
          SRA    16,A5
          MOVE   A5,COLOR0       ; x_ref
          MOVE   *A0+,A11,1      ; Z at the reference
          MOVE   A11,@FACE_Z,1
          MOVE   *A0+,A12,1      ; its step a column
          MOVE   A12,INC2
          MOVE   *A0+,A9,1       ; its step a row
          MOVE   A9,@FACE_DZDY,1
          MOVE   A0,@FACE_PTS,1  ; the first point, for the last edge
          MOVI   7FFFFFFFh,SADDR ; the lowest y so far
          MOVI   80000000h,SPTCH ; and the highest
          MOVI   EDGES,A8        ; the edge table
          JRUC   face_point

face_point:
          MOVE   *A0+,A5,1       ; ax
          MOVE   *A0+,A6,1       ; ay
          MOVE   A6,B14
          CMP    B14,SADDR
          JRLE   face_lo         ; taken: not a lower y (priced so; the other way is as dear)
          MOVE   B14,SADDR
face_lo:  CMP    B14,SPTCH
          JRGE   face_hi         ; taken: not a higher y
          MOVE   B14,SPTCH
face_hi:  MOVE   A0,A10          ; the next point
          MOVE   COUNT,A9
          SUBK   1,A9
          JRNZ   face_b          ; taken: not the last point
          MOVE   @FACE_PTS,A10,1 ; the last point's edge goes back to the first
face_b:   MOVE   *A10+,A9,1      ; bx
          MOVE   *A10,A10,1      ; by
          MOVE   A6,A7
          SUB    A10,A7          ; nx = ay - by
          SUB    A5,A9           ; ny = bx - ax
          MOVK   1,A14           ; the bias: 1 ...
          MOVE   A7,A7
          JRGT   face_tie        ; taken: nx > 0 (nx < 0 is as dear; FACE:levelpoint)
          JRNZ   face_bias       ; taken
          MOVE   A9,A9
          JRLE   face_bias       ; taken: ... unless nx = 0 and ny > 0, a level top edge
face_tie: CLR    A14
face_bias:
          NEG    A5
          ADDI   128,A5          ; 128 - ax
          NEG    A6
          ADDI   128,A6          ; 128 - ay
          MOVE   A7,A12
          MPYS   A5,A12          ; nx (128 - ax): A12 high, A13 low
          MOVE   A9,A10
          MPYS   A6,A10          ; ny (128 - ay): A10 high, A11 low
          ADD    A11,A13
          ADDC   A10,A12         ; k0
          SUB    A14,A13         ; less the bias
          JRNC   face_k          ; taken: no borrow
          SUBK   1,A12
face_k:   SRL    8,A13           ; N0 = (k0 - bias) >> 8, 64 bits
          MOVE   A12,A14
          SLL    24,A14
          OR     A14,A13
          SRA    8,A12
          MOVE   A9,*A8+,1       ; ny
          MOVE   A13,*A8+,1      ; N0, low and high
          MOVE   A12,*A8+,1
          MOVE   A7,*A8+,1       ; nx
          DSJ    COUNT,face_point ; taken: more points

face_close:
          MOVE   SADDR,A5        ; the rows whose centres the face may cover:
          ADDI   127,A5          ; from ceil((lowest y - 128) / 256)
          SRA    8,A5
          MOVE   SPTCH,A6
          SUBI   128,A6          ; to floor((highest y - 128) / 256)
          SRA    8,A6
          MOVE   WEND,A9
          SRA    16,A9           ; the frame's last row
          CMP    A9,A6
          JRLE   face_b1         ; taken: not below the frame
          MOVE   A9,A6
face_b1:  MOVE   A5,A5
          JRNN   face_t1         ; taken: not above it
          CLR    A5
face_t1:  MOVE   A5,DADDR        ; the first row and the last in the frame (no FILL
          MOVE   A6,DYDX         ; here: DADDR and DYDX hold them)
          MOVE   @FACE_REF,A9,1  ; Z at the reference column of the first row
          SRA    16,A9
          MOVE   A5,A11
          SUB    A9,A11          ; first - y_ref
          MOVE   @FACE_DZDY,A9,1
          MOVE   A9,SPTCH        ; (Z's step a row, kept for the rows)
          MPYS   A9,A11          ; (A11 odd: the product's low 32 bits)
          MOVE   @FACE_Z,A9,1
          ADD    A9,A11
          MOVE   A11,SADDR       ; kept for the rows
          MOVI   EDGES,A9
          MOVE   A9,COUNT        ; the edge table
          MOVI   face_step,A9
          MOVE   A9,INC1         ; where a run's pixel loop returns
          JRUC   face_row


;--- TIGA's call around a primitive: the set-up band's dear end -----------------------------
; Never run by this executive: what TIGA's graphics manager adds around each primitive it
; calls for a C packet, priced like the rest and added to C_cmd at the dear end of the
; listing's band (docs/COST_MODEL.md, "TIGA's call"). Its instruction mix is that of TI's
; C-callable primitives (TIGA r2.01, EXTPRIMS/FILLRECT.ASM and DRAWLINE.ASM): the call,
; the registers the primitive alters saved and restored (MMTM, MMFM), four arguments popped
; off the C stack and paired into XY words, the environment's destination bit-map tested
; and its viewport origin added to both points, the C stack pointer restored, the return.
tiga_call: CALLA tiga_prim       ; the graphics manager calls the primitive
tiga_prim: MMTM  SP,A0,A1
          MMTM   SP,B2,B7,B10,B11,B12,B13,B14
          MOVE   *-A14,A0,1      ; x
          MOVE   *-A14,A1,1      ; y
          SLL    16,A1
          MOVY   A1,A0           ; y:x
          MOVE   *-A14,A1,1      ; the second x (or the width)
          MOVE   *-A14,A8,1      ; the second y (or the height)
          SLL    16,A8
          MOVY   A8,A1
          MOVE   @ENV_DSTBM,A8,1 ; drawing to the screen?
          JRNZ   tiga_ret        ; not taken: it is
          MOVE   @ENV_ORIGIN,A8,1
          ADDXY  A8,A0           ; the viewport's origin added
          ADDXY  A8,A1
tiga_ret: MMFM   SP,B2,B7,B10,B11,B12,B13,B14
          MMFM   SP,A0,A1
          MOVE   *SP(32),A14,1   ; the C stack pointer back
          RETS   2

; by opcode (MARKER, 4, is never sent; 6 and 7 are the stream's time records); DRAW_SPAN's
; entry is span_line when the profile draws spans with LINE, FRAME_BEGIN's frame_begin_fill
; when it clears by FILL
table:    .long  0, frame_begin, fill_rect, span_fill, 0, frame_end, 0, 0, depth_clear
          .long  depth_span, face
