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
module em703_iso
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use em703_sim, only: run_t, seg_t, walker_t, walk_start, next_seg, SEG_LINE, SEG_TRAVEL, &
                         SEG_ARC, SEG_DOT, SEG_RAISE, LINE_SPEED, ARC_SPEED
    use em703_gcode, only: chord_count, plain => clean
    use em703_split, only: frames_needed, split_frame
    use base_text, only: text_t, str
    use base_error, only: error_t
    implicit none
    private
    public :: iso_program, geometric_code, signed_digits, iso_check, g_group, m_group

    !> Blocks of one program (three digits).
    integer, parameter, public :: ISO_BLOCKS = 999
    !> The longest dimension word, in units of 0.01 mm (999.99 mm; the
    !> format's six digits hold 999.999).
    integer(int64), parameter, public :: MAX_WORD = 99999
    !> Blocks kept free at the end of a program for raising the tool and M02.
    integer, parameter :: RESERVE = 2
    character(len=*), parameter :: Z_DOWN = 'Z-001000', Z_UP = 'Z+001000'

    type :: state_t
        integer :: n = 0                 !< last block number of this program
        integer :: part = 1              !< program number
        logical :: down = .false.
        integer :: feed = 0              !< current F code (0 = none yet)
        integer(int64) :: x = 0, y = 0   !< where the tool is, units
        character(len=:), allocatable :: title
    end type state_t

contains

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
    !> another, each after T<l> M06). err: a tape that cannot be walked.
    subroutine iso_program(runs, labels, title, chord_tol, text, err)
        type(run_t), intent(in) :: runs(:)
        character(len=*), intent(in) :: labels(:)
        character(len=*), intent(in) :: title
        real(real64), intent(in) :: chord_tol
        type(text_t), intent(inout) :: text
        type(error_t), allocatable, intent(out) :: err
        type(state_t) :: st
        type(walker_t) :: w
        type(seg_t) :: s
        logical :: got
        integer :: l
        st%title = title
        call text%add('%')
        call comment(text, title // ', block format of seed 004, increments in 0.001 mm')
        call comment(text, 'lines F' // two(geometric_code(LINE_SPEED)) // ', arcs F' // &
            two(geometric_code(ARC_SPEED)) // ', F the code of 1.12 to the power F mm/min, tool ' // &
            'down ' // Z_DOWN // ', up ' // Z_UP)
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
        call text%add('N' // three(st%n) // ' ' // words)
    end subroutine numbered

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
                ! 0.01 mm when not asked for
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

    !> Check a program of the document's block format, line by line. For
    !> each fault a message "block Nnnn (line L): ..." (or "line L: ...")
    !> is added to msgs (one a line); nprog, nblocks count what was read.
    subroutine iso_check(prog, msgs, nerr, nprog, nblocks)
        character(len=*), intent(in) :: prog
        type(text_t), intent(inout) :: msgs
        integer, intent(out) :: nerr, nprog, nblocks
        integer :: i, j, line, last_n
        logical :: inside
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
            call one_line(strip(prog(i:j - 1)))
            i = j + 1
        end do
        if (inside) call fault(0, 'the last program has no closing %')

    contains

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
            nerr = nerr + 1
            if (n > 0) then
                call msgs%add('block N' // three(n) // ' (line ' // str(line) // '): ' // what)
            else
                call msgs%add('line ' // str(line) // ': ' // what)
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
                call fault(0, 'a block begins with N and three digits, not "' // s(1:min(4, len(s))) // '"')
                return
            end if
            read (s(2:4), *) n
            if (len(s) > 4) then
                if (s(5:5) /= ' ') then
                    call fault(n, 'the block number has three digits')
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
                    call fault(n, 'no address "' // a // '" in the block format')
                    return
                end if
                q = p + 1
                do while (q <= len(s))
                    if (s(q:q) == ' ' .or. index(ORDER, s(q:q)) > 0) exit
                    q = q + 1
                end do
                ! the word is s(p:q-1)
                if (rank < last_rank .or. (rank == last_rank .and. a /= 'G' .and. a /= 'M')) then
                    call fault(n, 'the word ' // s(p:q - 1) // ' is out of the order N G X Y Z I J K F S T M')
                    return
                end if
                last_rank = rank
                select case (a)
                case ('X', 'Y', 'Z', 'I', 'J', 'K')
                    if (q - p /= 8 .or. index('+-', s(p + 1:p + 1)) == 0 .or. &
                        verify(s(p + 2:q - 1), '0123456789') > 0) then
                        call fault(n, 'the word ' // s(p:q - 1) // ' is not a sign and six digits')
                        return
                    end if
                case default
                    if (q - p /= 3 .or. verify(s(p + 1:q - 1), '0123456789') > 0) then
                        call fault(n, 'the word ' // s(p:q - 1) // ' is not two digits')
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
