; The command executive fb89's controller runs on a TMS34010: read the next command from
; the ring the host writes into the GSP's memory, dispatch on its opcode, load its operands
; into the B file and run FILL or LINE, and look for the next.
;
; This listing is what the controller's per-command cycles are counted from
; (controller_sim/gsp_listing.h): every instruction is priced from the data sheet's
; minimum-cycle tables (SPVS002C pp. 11-14) and the memory cycles its fields need
; (p. 19: two states a cycle, plus the profile's wait states); `fb89 controller-validate
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

HOST_WP   .equ  00001000h        ; where the host writes its write pointer
FRAME_NO  .equ  00001020h        ; the frame being drawn, for the host to read
HSTCTLL   .equ  0C00000F0h       ; host control, low byte: the message to the host
MSG_FRAME .equ  0010h            ; MSGOUT = 1: a frame is done
PSIZE     .equ  0C0000150h       ; the pixel size
ZBASE     .equ  00400000h        ; the depth buffer, in DRAM
VRAM_START .equ 010000000h       ; the frame buffer: the TDB's VRAM (CLEARFRM.ASM)
DPYCTL    .equ  0C0000080h       ; display control: ENV, SRE, SRT (TI's GSPREG.INC)
FPSHIFT   .equ  00001140h        ; log2 of the frame's pitch in bits (13: 1,024 pixels of 8)
ENV_DSTBM .equ  00001160h        ; TIGA's environment: the destination bit-map (TIGA_CALL)
ENV_ORIGIN .equ 00001180h        ; and the viewport's origin
ZSHIFT    .equ  00001040h        ; the depth word: 0 for 16 bits, 1 for 32
ZPITCH    .equ  00001060h        ; log2 of the depth buffer's row, in bits
FACE_REF  .equ  00001080h        ; a FACE's reference pixel, y:x
FACE_Z    .equ  000010A0h        ; its Z at the current row's reference column
FACE_DZDY .equ  000010C0h        ; its Z step a row
FACE_ROW  .equ  000010E0h        ; the row being drawn, and the last
FACE_END  .equ  00001100h
FACE_N    .equ  00001120h        ; its edge count
EDGES     .equ  00002000h        ; its edges, 4 longs each: x, remainder, x step, divisor

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
;@path DEPTH_SPAN:clip zclip zleft
;@path DEPTH_SPAN:outside depth_span take zout
;@path ZPIXEL16:nearer zloop16 zloop16
;@path ZPIXEL16:farther zloop16 zloop16 take zfar16
;@path ZPIXEL32:nearer zloop32 zloop32
;@path ZPIXEL32:farther zloop32 zloop32 take zfar32
;@path ZSPAN_EXIT zdone
;@path FACE face face_point
;@path FACE:point face_point face_point
;@path FACE:last face_close face_row
;@path FACE:row face_row face_edge
;@path FACE:edge face_edge face_edge
;@path FACE:span face_test zloop16
;@path FACE:empty face_test face_row take face_empty
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
          MOVK   8,A5
          MOVE   A5,@PSIZE,0
          JRUC   next

frame_begin_fill:
          MOVE   *A0+,A5,0       ; the frame's number
          MOVE   A5,@FRAME_NO,0
          MOVE   *A0+,A6,1       ; height:width
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
          MOVE   DPTCH,A6        ; the frame's pitch and offset, kept
          MOVE   OFFSET,A7
          MOVE   @ZPITCH,A5,0
          MOVK   1,A8
          SLL    A5,A8           ; the depth buffer's pitch
          MOVE   A8,DPTCH
          MOVI   ZBASE,A5
          MOVE   A5,OFFSET
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
          CLR    DADDR
          MOVK   1,A5
          NEG    A5              ; all ones
          MOVE   A5,COLOR1
          FILL   XY              ; the clear
          MOVE   A6,DPTCH        ; the frame's pitch, offset and pixel size back
          MOVE   A7,OFFSET
          MOVK   8,A5
          MOVE   A5,@PSIZE,0
          JRUC   next

depth_span:
          MOVE   *A0+,A6,1       ; y:x0
          MOVE   *A0+,A9,0       ; x1
          MOVE   *A0+,A11,1      ; Z at x0
          MOVE   *A0+,A12,1      ; its step
          MOVE   *A0+,A14,0      ; the colour word
          MOVI   next,A7         ; where the pixel loop returns
dspan:    MOVE   A6,A10          ; (a FACE's row joins here with the same registers)
          SRA    16,A10          ; y
          JRN    zout            ; not taken: a row above the frame is outside
          MOVE   WEND,A5
          SRA    16,A5           ; the frame's last row
          CMP    A5,A10
          JRGT   zout            ; not taken: a row below it is outside
          MOVE   WEND,A5
          SLL    16,A5
          SRL    16,A5           ; the frame's last column
          CMP    A5,A9
          JRLE   zright          ; taken: x1 is inside (else it is cut to the last column)
          MOVE   A5,A9
zright:   MOVE   A6,A5
          SLL    16,A5
          SRA    16,A5           ; x0
          JRN    zclip           ; not taken: x0 is inside (DEPTH_SPAN:clip when not)
zleft:    SUB    A5,A9
          JRN    zout            ; not taken: something is left of the span
          ADDK   1,A9
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
          MOVE   @ZSHIFT,A9,0    ; the depth word (sets Z)
          JRNE   zloop32         ; not taken: a 16-bit word
          JRUC   zloop16

zclip:    MOVE   A5,A13
          NEG    A13             ; the pixels cut on the left
          MPYS   A12,A13         ; their steps of Z (A13 odd: 32 bits of product)
          ADD    A13,A11         ; Z at column 0
          SRL    16,A6
          SLL    16,A6           ; x0 = 0
          CLR    A5
          JRUC   zleft

zout:     JUMP   A7              ; nothing to draw

zloop16:  MOVE   *A8,A5,0        ; the depth word here
          MOVE   A11,A9
          SRL    12,A9           ; Z's top 16 of its 28 bits
          CMP    A5,A9
          JRHS   zfar16          ; not taken: nearer (taken: as near or farther)
          MOVE   A9,*A8,0        ; the new depth
          PIXT   A14,*A10        ; the pixel
zfar16:   ADDK   16,A8           ; the next depth word
          ADDK   8,A10           ; the next pixel
          ADD    A12,A11         ; Z's step
          DSJ    A13,zloop16     ; taken: more pixels (the last is a state cheaper)
zdone:    JUMP   A7              ; to the next command, or a FACE's next row

zloop32:  MOVE   *A8,A5,1        ; the depth word here
          CMP    A5,A11
          JRHS   zfar32          ; not taken: nearer (taken: as near or farther)
          MOVE   A11,*A8,1       ; the new depth
          PIXT   A14,*A10        ; the pixel
zfar32:   ADDK   32,A8           ; the next depth word
          ADDK   8,A10           ; the next pixel
          ADD    A12,A11         ; Z's step
          DSJ    A13,zloop32     ; taken: more pixels
          JUMP   A7

; FACE: each edge is set up once with its x where it meets the first row (an exact
; division, as protocol/coverage.h's row_span makes) and its step a row as a quotient and
; remainder, so that each row steps every edge by additions alone and gets the integers the
; division would; the row's covered run, from the nearest left edge to the nearest right
; one, goes to the depth loop as a span. (The edge arithmetic is written at the length of
; its 32-bit form, one MPYS and two DIVS an edge; the 64-bit corrections a coordinate over
; 2^15 grid units would need are left out.)
face:     MOVE   *A0+,A13,0      ; the point count
          MOVE   A13,@FACE_N,0
          MOVE   A13,PATTRN      ; (and in the B file, for the rows: no pattern is drawn)
          SUBK   1,A13           ; the points before the last
          MOVE   *A0+,A14,0      ; the colour word
          MOVE   *A0+,A6,1       ; y_ref:x_ref
          MOVE   A6,@FACE_REF,1
          MOVE   A6,A5
          SLL    16,A5
          SRA    16,A5
          MOVE   A5,COLOR0       ; x_ref, in the B file for the rows (FILL's COLOR0 is unused)
          MOVE   *A0+,A11,1      ; Z at the reference
          MOVE   *A0+,A12,1      ; its step a column
          MOVE   *A0+,A9,1       ; its step a row
          MOVE   A9,@FACE_DZDY,1
          MOVE   A11,@FACE_Z,1
          MOVI   EDGES,A8        ; the edge table
          CLR    A7              ; the top row so far
          JRUC   face_point

face_point:
          MOVE   *A0+,A5,1       ; an edge from this point
          MOVE   *A0+,A6,1
          MOVE   *A0,A9,1        ; to the next
          MOVE   A0,A10
          ADDK   32,A10
          MOVE   *A10,A10,1
          SUB    A6,A10          ; dy
          SUB    A5,A9           ; dx
          MOVE   A10,A5
          MPYS   A6,A5           ; the edge function at the first row's centres
          DIVS   A10,A5          ; its x there: quotient and remainder
          MOVE   A5,*A8+,1       ; x
          MOVE   A6,*A8+,1       ; remainder
          SLL    8,A9            ; a row is 256 grid units
          DIVS   A10,A9          ; its step a row: quotient and remainder
          MOVE   A9,*A8+,1       ; x step
          MOVE   A10,*A8+,1      ; divisor, negative for a right edge
          CMP    A6,A7
          JRGE   face_bot        ; taken: not a new top row
          MOVE   A6,A7
face_bot: DSJ    A13,face_point  ; taken: more points

face_close:
          MOVE   *A0+,A5,1       ; the last point's edge back to the first (as FACE:point)
          MOVE   *A0+,A6,1
          MOVE   A0,A10
          MOVE   @FACE_N,A9,0
          SLL    6,A9
          SUB    A9,A10          ; the first point, kept in the ring
          MOVE   *A10,A9,1
          SUB    A6,A10
          SUB    A5,A9
          MOVE   A10,A5
          MPYS   A6,A5
          DIVS   A10,A5
          MOVE   A5,*A8+,1
          MOVE   A6,*A8+,1
          SLL    8,A9
          DIVS   A10,A9
          MOVE   A9,*A8+,1
          MOVE   A10,*A8+,1
          MOVE   @FACE_DZDY,A5,1 ; Z at the reference column, a row above the first
          MOVE   @FACE_REF,A9,1
          SRA    16,A9
          SUB    A7,A9
          ADDK   1,A9
          NEG    A9
          MPYS   A9,A5
          MOVE   @FACE_Z,A11,1
          ADD    A5,A11
          MOVE   A11,@FACE_Z,1
          MOVE   A7,@FACE_ROW,1  ; the first row and the last, clipped to the frame
          MOVE   A6,@FACE_END,1
          JRUC   face_row

face_row: MOVE   @FACE_ROW,A6,1  ; the row
          MOVE   @FACE_END,A5,1
          CMP    A5,A6
          JRGT   face_done       ; not taken: a row to draw
          ADDK   1,A6
          MOVE   A6,@FACE_ROW,1
          MOVE   @FACE_Z,A11,1   ; Z at the reference column of this row
          MOVE   @FACE_DZDY,A5,1
          ADD    A5,A11
          MOVE   A11,@FACE_Z,1
          MOVE   WEND,A9         ; the run so far: the whole row
          SLL    16,A9
          SRL    16,A9
          CLR    A10
          MOVI   EDGES,A8
          MOVE   PATTRN,A13      ; the edges
          JRUC   face_edge

face_edge:
          MOVE   *A8+,A5,1       ; x
          MOVE   *A8+,A6,1       ; remainder
          MOVE   *A8+,A7,1       ; x step
          MOVE   *A8+,A11,1      ; divisor, negative for a right edge
          ADD    A7,A5           ; this row's x
          SUB    A11,A6          ; the remainder's step
          JRNN   face_keep       ; not taken: counted with a carry (a row without is cheaper)
          ADDK   1,A5
          ADD    A11,A6
face_keep:
          SUBI   128,A8
          MOVE   A5,*A8+,1
          MOVE   A6,*A8+,1
          ADDK   32,A8
          ADDK   32,A8
          MOVE   A11,A11         ; a right edge? (sets N)
          JRN    face_right      ; not taken: counted as a left edge (a right one is as dear)
          CMP    A5,A10
          JRGE   face_next       ; taken: not a nearer bound
          MOVE   A5,A10
          JRUC   face_next
face_right:
          CMP    A5,A9
          JRLE   face_next
          MOVE   A5,A9
face_next:
          DSJ    A13,face_edge   ; taken: more edges

face_test:
          CMP    A10,A9
          JRLT   face_empty      ; not taken: the run is not empty (FACE:empty when it is)
          MOVE   COLOR0,A5       ; x_ref: Z at the run's first pixel
          MOVE   A10,A6
          SUB    A5,A6           ; the columns from it
          MOVE   A12,A5
          MPYS   A6,A5
          MOVE   @FACE_Z,A11,1
          ADD    A5,A11
          MOVE   @FACE_ROW,A6,1  ; y:x_begin
          SLL    16,A6
          MOVX   A10,A6
          MOVI   face_row,A7     ; the pixel loop returns to the next row
          JRUC   dspan

face_empty:
          JRUC   face_row

face_done:
          JRUC   next

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
