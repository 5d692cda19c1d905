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
; handlers) or dispatches (the loop).
;
; Set once at start-up, outside the counted paths: field 0 is 16 bits and field 1 32 bits
; (SETF 16,0,0 and SETF 32,0,1), PSIZE and DPTCH for the frame, the window to the frame
; with clipping on (CONTROL's W = 3), and the registers below.
;   A0  the ring's read pointer (a bit address)     A1  the host's write pointer, last read
;   A2  the ring's end                              A3  the ring's start
;   A4  the dispatch table                          A5-A8  scratch
;
; The host writes each command as 16-bit words (docs/COST_MODEL.md, "Modelled bytes"):
;   FRAME_BEGIN  opcode, frame, width, height, background
;   FILL_RECT    opcode, x, y, w, h, colour
;   DRAW_SPAN    opcode, x0, y, x1, colour
;   FRAME_END    opcode
; x before y, so that one 32-bit field read makes an XY address (X in the low half).
; A colour word holds the pixel repeated to 16 bits.

HOST_WP   .equ  00001000h        ; where the host writes its write pointer
FRAME_NO  .equ  00001020h        ; the frame being drawn, for the host to read
HSTCTLL   .equ  0C00000F0h       ; host control, low byte: the message to the host
MSG_FRAME .equ  0010h            ; MSGOUT = 1: a frame is done

;@path COMMON next
;@path FRAME_BEGIN frame_begin
;@path FILL_RECT fill_rect
;@path DRAW_SPAN:line span_line
;@path DRAW_SPAN:fill span_fill
;@path FRAME_END frame_end

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

frame_begin:
          MOVE   *A0+,A5,0       ; the frame's number
          MOVE   A5,@FRAME_NO,0  ; kept for the host (a write: queued)
          MOVE   *A0+,DYDX,1     ; DYDX = height:width, the whole frame
          CLR    DADDR           ; from 0:0
          MOVE   *A0+,A5,0       ; the background's colour word
          MOVE   A5,A6
          SLL    16,A6
          OR     A6,A5           ; the pixel in all 32 bits
          MOVE   A5,COLOR1
          FILL   XY              ; the clear
          JRUC   next

fill_rect:
          MOVE   *A0+,DADDR,1    ; DADDR = y:x
          MOVE   *A0+,DYDX,1     ; DYDX = h:w
          MOVE   *A0+,A5,0       ; the colour word
          MOVE   A5,A6
          SLL    16,A6
          OR     A6,A5
          MOVE   A5,COLOR1
          FILL   XY
          JRUC   next

span_line:
          MOVE   *A0+,DADDR,1    ; DADDR = y:x0
          MOVE   *A0+,A7,0       ; x1
          MOVE   DADDR,A6
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

span_fill:
          MOVE   *A0+,DADDR,1    ; DADDR = y:x0
          MOVE   *A0+,A7,0       ; x1
          MOVE   DADDR,A6
          SLL    16,A6
          SRL    16,A6           ; x0
          SUB    A6,A7
          ADDK   1,A7            ; n = x1 - x0 + 1
          ADDI   10000h,A7       ; one row: DYDX = 1:n
          MOVE   A7,DYDX
          MOVE   *A0+,A5,0       ; the colour word
          MOVE   A5,A6
          SLL    16,A6
          OR     A6,A5
          MOVE   A5,COLOR1
          FILL   XY
          JRUC   next

frame_end:
          MOVI   MSG_FRAME,A5
          MOVE   A5,@HSTCTLL,0   ; tell the host the frame is done (an I/O register)
          JRUC   next

; by opcode (MARKER, 4, is never sent); DRAW_SPAN's entry is span_fill when the profile
; draws spans as one-row fills
table:    .long  0, frame_begin, fill_rect, span_line, 0, frame_end
