!> Simulated runs as a program in the block format of seed 004 (the textbook
!> chapter on NC tape codes), the dialect "iso-1970s" of em703 gcode, and the
!> reader's check of such a program ("ошибка перфоленты").
!>
!> The document's block: the block number, three digits ("всего возможно 999
!> номеров в одной программе"); G words of two digits; the dimensions X, Y, Z
!> with the sign of the move and six digits, three before and three after
!> the point (X+023100 is 23.100 mm); F and S as two-digit codes of a
!> geometric series of ratio 1.12 (code n is 1.12**n, 00 stop, 99 rapid); T
!> two digits; the M words of its table (M00, M02, M03, M04, M05, M06,
!> M38-M40). "The sign of the move" makes the dimensions increments: each
!> block says how far to go, as the interpolator's frames do; a move longer
!> than 999.99 mm is split (em703_split). I and J (the arc centre from the
!> arc's start) take the same form. G codes: G00 travel, G01 lines, G02 and
!> G03 arcs (clockwise, counter-clockwise), G17 the XY plane; nothing of
!> G40-G99. The tool goes down and up as Z moves (G01 Z-001000, G00
!> Z+001000), since the document's M table has no pen: M03-M05 are the
!> spindle's. There is no S word: the EM-703 has no spindle. Between the tapes
!> of a job the tool changes with T01 M06, T02 M06, T03 M06. A program of
!> more than 999 blocks is cut into programs of at most 999, each complete:
!> `%`, a comment naming the part, N001 G17, the tool lowered again if it was
!> down; at its end the tool raised, M02, `%`.
!>
!> The check: G words of one group in one block are a tape error (the
!> document: "не может быть в одном кадре функций G01 и G02 ... должно
!> выявляться СЧПУ ... в виде ошибки перфоленты"). The groups are the
!> document's ranges G00-G09, G10-G39, G40-G59 (the OCR prints "G49...G59";
!> its own example G02, G17, G45, G61, G83 takes one of each of five groups,
!> so G45 has one: G40), G60-G79, G80-G99. The M groups are ours, from the
!> table: program (M00, M02), spindle (M03, M04, M05), tool change (M06),
!> speed range (M38, M39, M40); an M code outside the table is an error too.
!>
!> The document's three kinds of frame ("фиксированный", "переменный",
!> "адресный кадр"). The address frame is the block above, each word with
!> its letter. The fixed and the variable frame carry the same words without
!> letters, in a fixed order of eleven slots (SLOT_NAME, SLOT_WIDTH):
!>
!>     slot   N  G00-G09  G10-G39  X  Y  Z  I  J  F  T  M
!>     width  3  2        2        7  7  7  7  7  2  2  2
!>
!> A fixed frame has every slot every block, 48 characters and the end of
!> block, whatever it carries: X Y Z I J the increment (+000000 for none),
!> the G slots, F and T the code in force (carried from the block that set
!> it), M the block's own M code; a slot with nothing in force (a G or F
!> before the first of the program, T before a tool change, M in a block
!> without one) is spaces of its width, so that the reader still finds
!> every slot by its position. A variable frame has the same slots, a TAB
!> (HT) before each slot after N; a slot whose value is the previous block's
!> is empty (its TAB stays), and the frame ends after its last slot that is
!> not empty. Each program (from its %) starts from nothing in force and no
!> move. The reader's check reads all three (iso_check's frame).
module em703_iso
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use em703_sim, only: run_t, seg_t, walker_t, walk_start, next_seg, SEG_LINE, SEG_TRAVEL, &
                         SEG_ARC, SEG_DOT, SEG_RAISE, LINE_SPEED, ARC_SPEED
    use em703_gcode, only: chord_count, plain => clean
    use em703_split, only: frames_needed, split_frame
    use base_text, only: text_t, str, octal, fixed, mm
    use base_error, only: error_t
    implicit none
    private
    public :: iso_program, geometric_code, signed_digits, iso_check, g_group, m_group, frame_kind

    !> Blocks of one program (three digits).
    integer, parameter, public :: ISO_BLOCKS = 999
    !> The longest dimension word, in units of 0.01 mm (999.99 mm; the
    !> format's six digits hold 999.999).
    integer(int64), parameter, public :: MAX_WORD = 99999
    !> Blocks kept free at the end of a program for raising the tool and M02.
    integer, parameter :: RESERVE = 2
    character(len=*), parameter :: Z_DOWN = 'Z-001000', Z_UP = 'Z+001000'

    !> The slots of the fixed and the variable frame, in order.
    integer, parameter, public :: NSLOTS = 11
    character(len=*), parameter, public :: SLOT_NAME(NSLOTS) = [character(len=7) :: 'N', &
        'G00-G09', 'G10-G39', 'X', 'Y', 'Z', 'I', 'J', 'F', 'T', 'M']
    integer, parameter, public :: SLOT_WIDTH(NSLOTS) = [3, 2, 2, 7, 7, 7, 7, 7, 2, 2, 2]
    !> The length of a fixed frame, the end of block aside.
    integer, parameter, public :: FIXED_LENGTH = sum(SLOT_WIDTH)
    integer, parameter :: S_N = 1, S_G1 = 2, S_G2 = 3, S_X = 4, S_J = 8, S_M = 11
    character(len=*), parameter :: NO_MOVE = '+000000', TAB = achar(9)
    !> The kinds of frame.
    integer, parameter, public :: FRAME_ADDRESS = 0, FRAME_FIXED = 1, FRAME_VARIABLE = 2
    !> The most characters of a program a message shows (then "...").
    integer, parameter :: SHOWN_MAX = 20

    type :: state_t
        integer :: n = 0                 !< last block number of this program
        integer :: part = 1              !< program number
        logical :: down = .false.
        integer :: feed = 0              !< current F code (0 = none yet)
        integer(int64) :: x = 0, y = 0   !< where the tool is, units
        character(len=:), allocatable :: title
        integer :: frame = FRAME_ADDRESS
        !> fixed and variable frames: the slots of this block and of the previous
        character(len=7) :: cur(NSLOTS) = '', prev(NSLOTS) = ''
    end type state_t

contains

    !> The kind of frame named "address", "fixed" or "variable"; -1 for another name.
    integer function frame_kind(name)
        character(len=*), intent(in) :: name
        select case (name)
        case ('address'); frame_kind = FRAME_ADDRESS
        case ('fixed'); frame_kind = FRAME_FIXED
        case ('variable'); frame_kind = FRAME_VARIABLE
        case default; frame_kind = -1
        end select
    end function frame_kind

    !> The value of slot k when nothing is in force: no move, or spaces.
    pure function empty_slot(k) result(v)
        integer, intent(in) :: k
        character(len=7) :: v
        v = ''
        if (k >= S_X .and. k <= S_J) v = NO_MOVE
    end function empty_slot

    !> The two-digit code of a feed or speed: n with 1.12**n nearest to value
    !> on the logarithmic scale, 01 to 98 (00 is stop, 99 rapid).
    integer function geometric_code(value) result(n)
        real(real64), intent(in) :: value
        if (value <= 0) then
            n = 0
            return
        end if
        n = nint(log(value) / log(1.12_real64))
        n = max(1, min(98, n))
    end function geometric_code

    !> A dimension in units (0.01 mm) as the document's sign and six digits,
    !> three before and three after the point: 2310 -> "+023100".
    function signed_digits(units) result(s)
        integer(int64), intent(in) :: units
        character(len=:), allocatable :: s
        character(len=:), allocatable :: d
        d = str(abs(units) * 10 + 1000000_int64)
        s = merge('-', '+', units < 0) // d(2:7)
    end function signed_digits

    function two(n) result(s)
        integer, intent(in) :: n
        character(len=2) :: s
        s = achar(iachar('0') + n / 10) // achar(iachar('0') + mod(n, 10))
    end function two

    function three(n) result(s)
        integer, intent(in) :: n
        character(len=3) :: s
        s = achar(iachar('0') + n / 100) // achar(iachar('0') + mod(n / 10, 10)) // &
            achar(iachar('0') + mod(n, 10))
    end function three

    !> The program for one or more runs (the tapes of a job one after
    !> another, each after T<l> M06), in frames of kind frame (FRAME_ADDRESS
    !> when absent). err: a tape that cannot be walked.
    subroutine iso_program(runs, labels, title, chord_tol, text, err, frame)
        type(run_t), intent(in) :: runs(:)
        character(len=*), intent(in) :: labels(:)
        character(len=*), intent(in) :: title
        real(real64), intent(in) :: chord_tol
        type(text_t), intent(inout) :: text
        type(error_t), allocatable, intent(out) :: err
        integer, intent(in), optional :: frame
        type(state_t) :: st
        type(walker_t) :: w
        type(seg_t) :: s
        logical :: got
        integer :: l
        st%title = title
        if (present(frame)) st%frame = frame
        call text%add('%')
        call comment(text, title // ', block format of seed 004, increments in 0.001 mm')
        call comment(text, 'lines F' // two(geometric_code(LINE_SPEED)) // ', arcs F' // &
            two(geometric_code(ARC_SPEED)) // ', F the code of 1.12 to the power F mm/min, tool ' // &
            'down ' // Z_DOWN // ', up ' // Z_UP)
        if (chord_tol > 0) call comment(text, 'arcs as chords within ' // fixed(chord_tol, 4) // ' mm')
        select case (st%frame)
        case (FRAME_FIXED)
            call comment(text, 'fixed frames of ' // str(FIXED_LENGTH) // ' characters, no ' // &
                'letters, the slots N G G X Y Z I J F T M, every slot in every frame')
        case (FRAME_VARIABLE)
            call comment(text, 'variable frames, no letters, the slots N G G X Y Z I J F T M ' // &
                'with a TAB before each after N, an empty slot the value of the frame before')
        end select
        call block(st, text, 'G17')
        do l = 1, size(runs)
            call comment(text, trim(labels(l)))
            if (size(runs) > 1) then
                call up(st, text)
                call block(st, text, 'T' // two(l) // ' M06')
            end if
            call walk_start(w, runs(l), err)
            if (allocated(err)) return
            do
                call next_seg(w, runs(l), s, got)
                if (.not. got) exit
                call move(st, text, s, chord_tol)
            end do
        end do
        call up(st, text)
        call block(st, text, 'M02')
        call text%add('%')
    end subroutine iso_program

    subroutine comment(text, words)
        type(text_t), intent(inout) :: text
        character(len=*), intent(in) :: words
        call text%add('(' // plain(words) // ')')
    end subroutine comment

    !> A block numbered in this program; a new program first when this one
    !> has no room left. fcode > 0: the block needs that feed (F written when
    !> it changes, and again at the start of every program).
    subroutine block(st, text, words, fcode)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        character(len=*), intent(in) :: words
        integer, intent(in), optional :: fcode
        character(len=:), allocatable :: f
        if (st%n >= ISO_BLOCKS - RESERVE) call next_part(st, text)
        f = ''
        if (present(fcode)) then
            if (st%feed /= fcode) f = ' F' // two(fcode)
            st%feed = fcode
        end if
        call numbered(st, text, words // f)
    end subroutine block

    subroutine numbered(st, text, words)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        character(len=*), intent(in) :: words
        st%n = st%n + 1
        if (st%frame == FRAME_ADDRESS) then
            call text%add('N' // three(st%n) // ' ' // words)
        else
            call slotted(st, text, words)
        end if
    end subroutine numbered

    !> The block N<st%n> words (address words of this module, one space
    !> between) as a fixed or a variable frame.
    subroutine slotted(st, text, words)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        character(len=*), intent(in) :: words
        character(len=:), allocatable :: line
        integer :: k, p, q, last
        if (st%n == 1) then
            do k = 1, NSLOTS
                st%cur(k) = empty_slot(k)
            end do
            st%prev = st%cur
        end if
        do k = S_X, S_J
            st%cur(k) = NO_MOVE
        end do
        st%cur(S_M) = ''
        st%cur(S_N) = three(st%n)
        p = 1
        do while (p <= len(words))
            q = index(words(p:), ' ')
            q = merge(len(words), p + q - 2, q == 0)
            st%cur(slot_of(words(p:q))) = words(p + 1:q)
            p = q + 2
        end do
        if (st%frame == FRAME_FIXED) then
            line = ''
            do k = 1, NSLOTS
                line = line // st%cur(k)(1:SLOT_WIDTH(k))
            end do
        else
            last = 1
            do k = 2, NSLOTS
                if (st%cur(k) /= st%prev(k)) last = k
            end do
            line = st%cur(S_N)(1:SLOT_WIDTH(S_N))
            do k = 2, last
                line = line // TAB
                if (st%cur(k) /= st%prev(k)) line = line // st%cur(k)(1:SLOT_WIDTH(k))
            end do
        end if
        st%prev = st%cur
        call text%add(line)
    end subroutine slotted

    !> The slot of an address word of this module (G by its group).
    integer function slot_of(word) result(k)
        character(len=*), intent(in) :: word
        k = index('NGGXYZIJFTM', word(1:1))
        if (word(1:1) == 'G') then
            if (word(2:3) >= '10') k = S_G2
        end if
    end function slot_of

    !> End this program (tool up, M02, %) and start the next, in the state
    !> the tool was in.
    subroutine next_part(st, text)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        logical :: was_down
        was_down = st%down
        if (st%down) call numbered(st, text, 'G00 ' // Z_UP)
        call numbered(st, text, 'M02')
        call text%add('%')
        st%part = st%part + 1
        st%n = 0
        st%feed = 0
        call text%add('%')
        call comment(text, st%title // ', program ' // str(st%part) // ', going on from the ' // &
                     'end of program ' // str(st%part - 1))
        call numbered(st, text, 'G17')
        if (was_down) then
            st%feed = geometric_code(LINE_SPEED)
            call numbered(st, text, 'G01 ' // Z_DOWN // ' F' // two(st%feed))
        end if
    end subroutine next_part

    subroutine down(st, text)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        if (st%down) return
        call block(st, text, 'G01 ' // Z_DOWN, geometric_code(LINE_SPEED))
        st%down = .true.
    end subroutine down

    subroutine up(st, text)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        if (.not. st%down) return
        call block(st, text, 'G00 ' // Z_UP)
        st%down = .false.
    end subroutine up

    !> Straight to (tx, ty) units with G00 or G01, split into moves of at
    !> most MAX_WORD per axis.
    subroutine straight(st, text, g, tx, ty, fcode)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        character(len=*), intent(in) :: g
        integer(int64), intent(in) :: tx, ty
        integer, intent(in) :: fcode
        integer(int64) :: n, k, fx, fy, dx, dy
        dx = tx - st%x
        dy = ty - st%y
        n = frames_needed(dx, dy, MAX_WORD)
        do k = 1, n
            call split_frame(dx, dy, k, n, fx, fy)
            if (fcode > 0) then
                call block(st, text, g // ' X' // signed_digits(fx) // ' Y' // signed_digits(fy), fcode)
            else
                call block(st, text, g // ' X' // signed_digits(fx) // ' Y' // signed_digits(fy))
            end if
        end do
        st%x = tx
        st%y = ty
    end subroutine straight

    subroutine move(st, text, s, chord_tol)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        type(seg_t), intent(in) :: s
        real(real64), intent(in) :: chord_tol
        integer :: n, j
        real(real64) :: a, r, r0, r1, cx, cy
        integer(int64) :: ci, cj
        select case (s%kind)
        case (SEG_TRAVEL)
            call up(st, text)
            call straight(st, text, 'G00', s%x1, s%y1, 0)
        case (SEG_RAISE)
            call up(st, text)
        case (SEG_DOT)
            call down(st, text)
        case (SEG_LINE)
            call down(st, text)
            call straight(st, text, 'G01', s%x1, s%y1, geometric_code(LINE_SPEED))
        case (SEG_ARC)
            call down(st, text)
            ci = s%cx - s%x0
            cj = s%cy - s%y0
            if (chord_tol <= 0 .and. max(abs(ci), abs(cj), abs(s%x1 - s%x0), abs(s%y1 - s%y0)) &
                <= MAX_WORD) then
                call block(st, text, merge('G02', 'G03', s%sweep < 0) // ' X' // &
                    signed_digits(s%x1 - s%x0) // ' Y' // signed_digits(s%y1 - s%y0) // &
                    ' I' // signed_digits(ci) // ' J' // signed_digits(cj), &
                    geometric_code(ARC_SPEED))
                st%x = s%x1
                st%y = s%y1
            else
                ! chords (asked for, or an arc too large for I and J): within
                ! 0.01 mm when not asked for, and said so
                if (chord_tol <= 0) call comment(text, 'an arc of radius ' // mm(nint(s%r, int64)) // &
                    ' mm, too large for the six digits of I and J, as chords within 0.0100 mm')
                r0 = s%r / 100
                r1 = hypot(real(s%x1 - s%cx, real64), real(s%y1 - s%cy, real64)) / 100
                cx = real(s%cx, real64) / 100
                cy = real(s%cy, real64) / 100
                n = chord_count(max(r0, r1), s%sweep, merge(chord_tol, 0.01_real64, chord_tol > 0))
                do j = 1, n - 1
                    a = s%a0 + s%sweep * j / n
                    r = r0 + (r1 - r0) * j / n
                    call straight(st, text, 'G01', nint((cx + r * cos(a)) * 100, int64), &
                                  nint((cy + r * sin(a)) * 100, int64), geometric_code(ARC_SPEED))
                end do
                call straight(st, text, 'G01', s%x1, s%y1, geometric_code(ARC_SPEED))
            end if
        end select
    end subroutine move

    !> Characters of a program for a message: the first SHOWN_MAX of them,
    !> then "..." when there are more; a byte that is not a printable ASCII
    !> character (below 32, 127, above 127) shown as its octal code in angle
    !> brackets, the code em703 view prints for its row: <011> a TAB, <177>
    !> a delete. Built in one pass into a string of the length it will have,
    !> so that a line of any length costs a message of at most
    !> 5 * SHOWN_MAX + 3 characters and nothing reaches the terminal raw.
    function shown(s) result(t)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: t
        integer :: i, m, n
        m = min(len(s), SHOWN_MAX)
        n = m
        do i = 1, m
            if (.not. printable(s(i:i))) n = n + 4
        end do
        if (len(s) > m) n = n + 3
        allocate(character(len=n) :: t)
        n = 0
        do i = 1, m
            if (printable(s(i:i))) then
                t(n + 1:n + 1) = s(i:i)
                n = n + 1
            else
                t(n + 1:n + 5) = '<' // octal(iachar(s(i:i)), 3) // '>'
                n = n + 5
            end if
        end do
        if (len(s) > m) t(n + 1:n + 3) = '...'
    end function shown

    pure logical function printable(ch)
        character, intent(in) :: ch
        printable = iachar(ch) >= 32 .and. iachar(ch) <= 126
    end function printable

    ! ------------------------------------------------------------------
    !> The group of G code g (0..99): 1 G00-G09, 2 G10-G39, 3 G40-G59,
    !> 4 G60-G79, 5 G80-G99.
    integer function g_group(g)
        integer, intent(in) :: g
        select case (g)
        case (0:9); g_group = 1
        case (10:39); g_group = 2
        case (40:59); g_group = 3
        case (60:79); g_group = 4
        case default; g_group = 5
        end select
    end function g_group

    !> The group of M code m: 1 program (M00, M02), 2 spindle (M03-M05), 3
    !> tool change (M06), 4 speed range (M38-M40); 0 not in the table.
    integer function m_group(m)
        integer, intent(in) :: m
        select case (m)
        case (0, 2); m_group = 1
        case (3:5); m_group = 2
        case (6); m_group = 3
        case (38:40); m_group = 4
        case default; m_group = 0
        end select
    end function m_group

    !> Check a program of the document's block format, line by line, its
    !> blocks in frames of kind frame (FRAME_ADDRESS when absent). For
    !> each fault a message "block Nnnn (line L): ..." (or "line L: ...")
    !> is added to msgs (one a line); nprog, nblocks count what was read.
    !> When the program was read from a tape, rows(L) is the tape row where
    !> line L starts, and each message names it too: "(line L, tape row R)".
    !> A fixed or a variable frame is read slot by slot (a variable frame's
    !> empty slot is the previous block's value) into the address block it
    !> stands for, which is then checked as an address block is.
    subroutine iso_check(prog, msgs, nerr, nprog, nblocks, frame, rows)
        character(len=*), intent(in) :: prog
        type(text_t), intent(inout) :: msgs
        integer, intent(out) :: nerr, nprog, nblocks
        integer, intent(in), optional :: frame
        integer, intent(in), optional :: rows(:)
        integer :: i, j, line, last_n, kind
        logical :: inside
        character(len=7) :: prev(NSLOTS)
        kind = FRAME_ADDRESS
        if (present(frame)) kind = frame
        prev = ''
        nerr = 0
        nprog = 0
        nblocks = 0
        line = 0
        last_n = 0
        inside = .false.
        i = 1
        do while (i <= len(prog))
            j = index(prog(i:), achar(10))
            if (j == 0) then
                j = len(prog) + 1
            else
                j = i + j - 1
            end if
            line = line + 1
            call read_line(strip(prog(i:j - 1)))
            i = j + 1
        end do
        if (inside) call fault(0, 'the last program has no closing %')

    contains

        !> A line in frames of kind: an address block as it is, a fixed or
        !> variable frame as the address block it stands for.
        subroutine read_line(s)
            character(len=*), intent(in) :: s
            character(len=:), allocatable :: addr
            integer :: k
            if (kind == FRAME_ADDRESS .or. len(s) == 0 .or. .not. inside) then
                call one_line(s)
            else if (s == '%' .or. s(1:1) == '(') then
                call one_line(s)
            else
                if (kind == FRAME_FIXED) then
                    call read_fixed(s, addr)
                else
                    call read_variable(s, addr)
                end if
                if (allocated(addr)) then
                    call one_line(addr)
                else
                    nblocks = nblocks + 1
                end if
            end if
            if (s == '%' .and. inside) then
                do k = 1, NSLOTS
                    prev(k) = empty_slot(k)
                end do
            end if
        end subroutine read_line

        !> The block number of a frame for its messages (0: none readable).
        integer function number_of(s) result(n)
            character(len=*), intent(in) :: s
            n = 0
            if (len(s) >= 3) then
                if (verify(s(1:3), '0123456789') == 0) read (s(1:3), *) n
            end if
        end function number_of

        !> Whether v is a value of slot k: digits, a sign and digits, or
        !> (G, F, T, M) spaces; why not in why.
        logical function slot_ok(k, v, why) result(ok)
            integer, intent(in) :: k
            character(len=*), intent(in) :: v
            character(len=:), allocatable, intent(out) :: why
            integer :: g
            ok = .false.
            if (index(v, TAB) > 0) then
                why = 'has a TAB in it'
                return
            end if
            if (k >= S_X .and. k <= S_J) then
                why = 'is not a sign and six digits'
                if (len(v) /= 7) return
                if (index('+-', v(1:1)) == 0 .or. verify(v(2:7), '0123456789') > 0) return
            else if (k == S_N) then
                why = 'is not three digits'
                if (len(v) /= 3) return
                if (verify(v, '0123456789') > 0) return
            else
                why = 'is not two digits (nor two spaces, no word)'
                if (len(v) /= 2) return
                if (v == '  ') then
                    ok = .true.
                    return
                end if
                if (verify(v, '0123456789') > 0) return
                if (k == S_G1 .or. k == S_G2) then
                    read (v, *) g
                    if (g_group(g) /= k - S_G1 + 1) then
                        why = 'is G' // v // ', not of ' // trim(SLOT_NAME(k)) // ', the codes ' // &
                              'this slot takes'
                        return
                    end if
                end if
            end if
            why = ''
            ok = .true.
        end function slot_ok

        !> The address block of the slots v (spaces: no word).
        function address_block(v) result(addr)
            character(len=7), intent(in) :: v(NSLOTS)
            character(len=:), allocatable :: addr
            integer :: k
            addr = 'N' // v(S_N)(1:3)
            do k = 2, NSLOTS
                if (len_trim(v(k)) > 0) addr = addr // ' ' // SLOT_NAME(k)(1:1) // &
                                               v(k)(1:SLOT_WIDTH(k))
            end do
        end function address_block

        !> A fixed frame: every slot at its columns, FIXED_LENGTH characters.
        subroutine read_fixed(s, addr)
            character(len=*), intent(in) :: s
            character(len=:), allocatable, intent(out) :: addr
            character(len=7) :: v(NSLOTS)
            character(len=:), allocatable :: why, where, hint
            integer :: k, c, n
            n = number_of(s)
            hint = ''
            if (index(s, TAB) > 0) then
                hint = ' (a TAB at column ' // str(index(s, TAB)) // ': a variable frame? see --frame)'
            else if (s(1:1) == 'N') then
                hint = ' (a letter address: an address frame? see --frame)'
            end if
            c = 1
            do k = 1, NSLOTS
                where = 'slot ' // trim(SLOT_NAME(k)) // ' (columns ' // str(c) // '-' // &
                        str(c + SLOT_WIDTH(k) - 1) // ')'
                if (c + SLOT_WIDTH(k) - 1 > len(s)) then
                    if (c <= len(s)) then
                        why = 'it ends in ' // where // ', which is cut short'
                    else if (k == NSLOTS) then
                        why = where // ' is missing'
                    else
                        why = 'slots ' // trim(SLOT_NAME(k)) // ' to ' // trim(SLOT_NAME(NSLOTS)) // &
                              ' (columns ' // str(c) // '-' // str(FIXED_LENGTH) // ') are missing'
                    end if
                    call fault(n, 'a fixed frame has ' // str(FIXED_LENGTH) // ' characters, ' // &
                        'this one ' // str(len(s)) // ': ' // why // hint)
                    return
                end if
                if (.not. slot_ok(k, s(c:c + SLOT_WIDTH(k) - 1), why)) then
                    if (len(s) /= FIXED_LENGTH) why = why // '; the frame has ' // str(len(s)) // &
                        ' characters, a fixed frame ' // str(FIXED_LENGTH)
                    call fault(n, where // ' "' // shown(s(c:c + SLOT_WIDTH(k) - 1)) // '" ' // why // hint)
                    return
                end if
                v(k) = s(c:c + SLOT_WIDTH(k) - 1)
                c = c + SLOT_WIDTH(k)
            end do
            if (len(s) > FIXED_LENGTH) then
                call fault(n, 'a fixed frame has ' // str(FIXED_LENGTH) // ' characters, this ' // &
                    'one ' // str(len(s)) // ': "' // shown(s(c:)) // &
                    '" after slot M (from column ' // str(c) // ')' // hint)
                return
            end if
            addr = address_block(v)
        end subroutine read_fixed

        !> A variable frame: the slots in order, a TAB before each after N, an
        !> empty one the previous block's value, the slots after the last the
        !> previous block's values.
        subroutine read_variable(s, addr)
            character(len=*), intent(in) :: s
            character(len=:), allocatable, intent(out) :: addr
            character(len=7) :: v(NSLOTS)
            character(len=:), allocatable :: why, where
            integer :: k, p, q, n
            n = number_of(s)
            if (s(1:1) == 'N') then
                call fault(n, 'a variable frame begins with its number, three digits, not "' // &
                           shown(s(1:min(4, len(s)))) // '" (a letter address: an address frame? ' // &
                           'see --frame)')
                return
            end if
            v = prev
            p = 1
            k = 0
            do
                k = k + 1
                q = index(s(p:), TAB)
                q = merge(len(s) + 1, p + q - 1, q == 0)
                if (k > NSLOTS) then
                    call fault(n, 'a variable frame has at most ' // str(NSLOTS) // ' slots ' // &
                        '(N G G X Y Z I J F T M, ' // str(NSLOTS - 1) // ' TABs), this one more: ' // &
                        'a TAB too many (the ' // str(NSLOTS) // 'th TAB, column ' // str(p - 1) // ')')
                    return
                end if
                where = 'slot ' // trim(SLOT_NAME(k)) // ' (' // trim(ordinal(k)) // ' slot, ' // &
                        'columns ' // str(p) // '-' // str(q - 1) // ')'
                if (q == p) then
                    if (k == S_N) then
                        call fault(n, 'slot N is empty: every frame begins with its number, ' // &
                                   'three digits')
                        return
                    end if
                else if (.not. slot_ok(k, s(p:q - 1), why)) then
                    if (k == S_N .and. q > len(s) .and. len(s) == FIXED_LENGTH) then
                        why = why // ' (' // str(q - p) // ' characters and no TAB, a fixed ' // &
                            'frame''s width: a fixed frame? see --frame)'
                    else if (q - p > SLOT_WIDTH(k)) then
                        why = why // ' (' // str(q - p) // ' characters, ' // str(SLOT_WIDTH(k)) // &
                            ' wanted: a TAB missing?)'
                    end if
                    call fault(n, where // ' "' // shown(s(p:q - 1)) // '" ' // why)
                    return
                else
                    v(k) = s(p:q - 1)
                end if
                if (q > len(s)) exit
                p = q + 1
            end do
            prev = v
            addr = address_block(v)
        end subroutine read_variable

        function ordinal(k) result(s)
            integer, intent(in) :: k
            character(len=:), allocatable :: s
            select case (k)
            case (1); s = '1st'
            case (2); s = '2nd'
            case (3); s = '3rd'
            case default; s = str(k) // 'th'
            end select
        end function ordinal

        function strip(s) result(t)
            character(len=*), intent(in) :: s
            character(len=:), allocatable :: t
            t = s
            if (len(t) > 0) then
                if (t(len(t):len(t)) == achar(13)) t = t(1:len(t) - 1)
            end if
        end function strip

        subroutine fault(n, what)
            integer, intent(in) :: n
            character(len=*), intent(in) :: what
            character(len=:), allocatable :: where
            nerr = nerr + 1
            where = 'line ' // str(line)
            if (present(rows)) then
                if (line >= 1 .and. line <= size(rows)) where = where // ', tape row ' // &
                                                                str(rows(line))
            end if
            if (n > 0) then
                call msgs%add('block N' // three(n) // ' (' // where // '): ' // what)
            else
                call msgs%add(where // ': ' // what)
            end if
        end subroutine fault

        subroutine one_line(s)
            character(len=*), intent(in) :: s
            integer :: n, p, q, rank, last_rank, v, gseen(5), mseen(0:4), grp
            character(len=1) :: a
            character(len=*), parameter :: ORDER = 'NGXYZIJKFSTM'
            if (len(s) == 0) return
            if (s == '%') then
                if (inside) then
                    inside = .false.
                else
                    inside = .true.
                    nprog = nprog + 1
                    last_n = 0
                end if
                return
            end if
            if (s(1:1) == '(') then
                if (s(len(s):len(s)) /= ')') call fault(0, 'a comment must end with )')
                return
            end if
            if (.not. inside) then
                call fault(0, 'a block outside a program (no % before it)')
                return
            end if
            nblocks = nblocks + 1
            if (len(s) < 4) then
                call fault(0, 'a block begins with N and three digits')
                return
            end if
            if (s(1:1) /= 'N' .or. verify(s(2:4), '0123456789') > 0) then
                if (verify(s(1:3), '0123456789') == 0) then
                    call fault(0, 'a block begins with N and three digits, not "' // shown(s(1:4)) // &
                               '" (no letter: a fixed or a variable frame? see --frame)')
                    return
                end if
                call fault(0, 'a block begins with N and three digits, not "' // &
                           shown(s(1:min(4, len(s)))) // '"')
                return
            end if
            read (s(2:4), *) n
            if (len(s) > 4) then
                if (s(5:5) /= ' ') then
                    q = index(s // ' ', ' ')
                    call fault(n, 'the block number has three digits, not "' // &
                               shown(s(1:min(q - 1, len(s)))) // '" (a blank after them)')
                    return
                end if
            end if
            if (n <= last_n) call fault(n, 'block numbers must increase (N' // three(last_n) // ' before)')
            last_n = n
            gseen = -1
            mseen = -1
            last_rank = 1
            p = 5
            do while (p <= len(s))
                if (s(p:p) == ' ') then
                    p = p + 1
                    cycle
                end if
                a = s(p:p)
                rank = index(ORDER, a)
                if (rank <= 1) then
                    call fault(n, 'no address "' // shown(a) // '" in the block format')
                    return
                end if
                q = p + 1
                do while (q <= len(s))
                    if (s(q:q) == ' ' .or. index(ORDER, s(q:q)) > 0) exit
                    q = q + 1
                end do
                ! the word is s(p:q-1)
                if (rank < last_rank .or. (rank == last_rank .and. a /= 'G' .and. a /= 'M')) then
                    call fault(n, 'the word ' // shown(s(p:q - 1)) // ' is out of the order ' // &
                               'N G X Y Z I J K F S T M')
                    return
                end if
                last_rank = rank
                select case (a)
                case ('X', 'Y', 'Z', 'I', 'J', 'K')
                    if (q - p /= 8 .or. index('+-', s(p + 1:p + 1)) == 0 .or. &
                        verify(s(p + 2:q - 1), '0123456789') > 0) then
                        call fault(n, 'the word ' // shown(s(p:q - 1)) // ' is not a sign and six digits')
                        return
                    end if
                case default
                    if (q - p /= 3 .or. verify(s(p + 1:q - 1), '0123456789') > 0) then
                        call fault(n, 'the word ' // shown(s(p:q - 1)) // ' is not two digits')
                        return
                    end if
                    read (s(p + 1:q - 1), *) v
                    if (a == 'G') then
                        grp = g_group(v)
                        if (gseen(grp) >= 0) call fault(n, 'ошибка перфоленты (tape error): G' // &
                            two(gseen(grp)) // ' and G' // two(v) // ' are of one group')
                        gseen(grp) = v
                    else if (a == 'M') then
                        grp = m_group(v)
                        if (grp == 0) then
                            call fault(n, 'M' // two(v) // ' is not in the document''s table ' // &
                                       '(M00 M02 M03 M04 M05 M06 M38 M39 M40)')
                        else
                            if (mseen(grp) >= 0) call fault(n, 'ошибка перфоленты (tape error): M' // &
                                two(mseen(grp)) // ' and M' // two(v) // ' are of one group')
                            mseen(grp) = v
                        end if
                    end if
                end select
                p = q
            end do
        end subroutine one_line

    end subroutine iso_check

end module em703_iso
