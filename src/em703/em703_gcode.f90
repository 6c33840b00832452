!> Simulated runs as an ISO 6983 (RS-274) program for a modern machine.
!>
!> `%`, then blocks numbered N1, N2, ... (after N99999 the numbers start
!> again at N1), millimetres (G21), absolute coordinates (G90) with the
!> start point as the origin, the XY plane (G17), feed per minute (G94).
!> Travel with the tool raised is G00; a drawn line G01 at the machine's line
!> speed (F5500); an arc or circle G02 (K13, clockwise) or G03 (K11,
!> counter-clockwise) with the centre as I, J relative to the arc's start, at
!> the arc speed (F1500). The tool goes down and up as M03 / M05 or, with
!> use_z, as Z moves (down G01 Z0.000, up G00 Z1.000). A dot is the tool
!> lowered and raised where it stands. M02 ends the program, then `%`.
!>
!> The GRBL 1.1 dialect (dialect "grbl"; GRBL is the firmware of most hobby
!> plotters, lasers and mills) writes only what GRBL 1.1 accepts: no `%` lines
!> (error:1), no tool change (T M06 is error:20: between tapes the program
!> pauses with M0 and a comment names the next tape and tool), only G and M
!> codes of GRBL's list (G0-G3, G17, G21, G90, G94; M0, M2, M3, M5), a feed
!> rate in the first block, and arcs whose end lies on their circle within
!> GRBL's check (error:33: the two radii may differ by 0.005 mm, or by 0.1 %
!> of the radius): a tape arc may end one unit (0.01 mm) off its circle, and
!> the centre of such an arc is moved onto the perpendicular bisector of the
!> chord, the point of the bisector nearest the tape's centre (the arc still
!> runs from the same start to the same end). Comments are kept under
!> GRBL's 80 characters a line.
!>
!> Line-only machines: chord_tol > 0 replaces every arc by equal chords with
!> the step angle of seed 002, 2*arccos(1 - tol/R), so that no point of a chord
!> is farther than tol (mm) from the arc; the bound keeps a margin for the
!> rounding of the chord ends to 0.001 mm. An arc's end may lie up to one unit
!> off the circle through its start (docs/TAPE.md, Frames); the chords then follow
!> the arc whose radius changes evenly from the start's to the end's, so that
!> the last chord ends exactly at the tape's end point.
module em703_gcode
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use em703_sim, only: run_t, seg_t, walker_t, walk_start, next_seg, SEG_LINE, SEG_TRAVEL, SEG_ARC, SEG_DOT, SEG_RAISE, &
                         TWO_PI, LINE_SPEED, ARC_SPEED
    use base_text, only: text_t, str, fixed, mm
    use base_error, only: error_t
    implicit none
    private
    public :: gcode_program, chord_count, clean

    !> Chord ends are written to 0.001 mm: each is within 0.00071 mm of the
    !> arc, so the chords are planned for tol - ROUNDING.
    real(real64), parameter, public :: ROUNDING = 0.0008_real64
    !> Height of the raised tool for use_z, mm.
    character(len=*), parameter :: Z_UP = '1.000', Z_DOWN = '0.000'

    type :: state_t
        integer :: n = 0                 !< last block number
        logical :: down = .false.
        integer :: feed = 0              !< current F (0 = none yet)
        logical :: use_z = .false.
        logical :: grbl = .false.        !< the GRBL 1.1 dialect
    end type state_t

    !> The longest comment of the GRBL dialect (GRBL reads 80 characters a line).
    integer, parameter :: GRBL_COMMENT = 70

contains

    !> Number of equal chords for an arc of radius r and sweep |sweep| (radians)
    !> so that each chord deviates at most tol - ROUNDING from the arc (all mm).
    integer function chord_count(r, sweep, tol) result(n)
        real(real64), intent(in) :: r, sweep, tol
        real(real64) :: t, step
        t = max(tol - ROUNDING, 1.0e-6_real64)
        step = 2 * acos(max(-1.0_real64, 1 - t / max(r, 1.0e-9_real64)))
        n = max(1, ceiling(abs(sweep) / step - 1.0e-9_real64))
    end function chord_count

    !> The program for one or more runs (tapes run one after another; for more
    !> than one, each starts with a tool change T<l> M06). labels: a comment for
    !> each tape; tools: tool widths in units (0 = unknown).
    subroutine gcode_program(runs, labels, tools, title, chord_tol, use_z, text, dialect)
        type(run_t), intent(in) :: runs(:)
        character(len=*), intent(in) :: labels(:)
        integer(int64), intent(in) :: tools(:)
        character(len=*), intent(in) :: title
        real(real64), intent(in) :: chord_tol      !< mm; 0 = keep the arcs
        logical, intent(in) :: use_z
        type(text_t), intent(inout) :: text
        character(len=*), intent(in), optional :: dialect   !< "linuxcnc" (default) or "grbl"
        type(state_t) :: st
        type(walker_t) :: w
        type(error_t), allocatable :: err
        type(seg_t) :: s
        logical :: got
        integer :: l
        st%use_z = use_z
        if (present(dialect)) st%grbl = dialect == 'grbl'
        if (.not. st%grbl) call text%add('%')
        call comment(st, text, title)
        call comment(st, text, 'units mm, absolute, origin at the start point, lines F' // &
            str(nint(LINE_SPEED)) // ', arcs F' // str(nint(ARC_SPEED)) // ' mm/min')
        if (chord_tol > 0) call comment(st, text, 'arcs as chords within ' // fixed(chord_tol, 4) // ' mm')
        if (st%grbl) then
            st%feed = nint(LINE_SPEED)
            call block(st, text, 'G21 G90 G17 G94 F' // str(st%feed))
        else
            call block(st, text, 'G21 G90 G17 G94')
        end if
        if (use_z) then
            call block(st, text, 'G00 Z' // Z_UP)
        else
            call block(st, text, 'M05')
        end if
        do l = 1, size(runs)
            if (tools(l) > 0) then
                call comment(st, text, trim(labels(l)) // ', tool ' // mm(tools(l)) // ' mm')
            else
                call comment(st, text, trim(labels(l)))
            end if
            if (size(runs) > 1) then
                call up(st, text)
                if (st%grbl) then
                    call block(st, text, 'M0')       ! pause: the operator changes the tool
                else
                    call block(st, text, 'T' // str(l) // ' M06')
                end if
            end if
            call walk_start(w, runs(l), err)
            if (allocated(err)) exit
            do
                call next_seg(w, runs(l), s, got)
                if (.not. got) exit
                call move(st, text, s, chord_tol)
            end do
        end do
        call up(st, text)
        call block(st, text, 'M02')
        if (.not. st%grbl) call text%add('%')
    end subroutine gcode_program

    !> A comment line; in the GRBL dialect cut to GRBL_COMMENT characters.
    subroutine comment(st, text, words)
        type(state_t), intent(in) :: st
        type(text_t), intent(inout) :: text
        character(len=*), intent(in) :: words
        if (st%grbl .and. len(words) > GRBL_COMMENT) then
            call text%add('(' // clean(words(1:GRBL_COMMENT)) // ')')
        else
            call text%add('(' // clean(words) // ')')
        end if
    end subroutine comment

    subroutine move(st, text, s, chord_tol)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        type(seg_t), intent(in) :: s
        real(real64), intent(in) :: chord_tol
        integer :: n, j
        real(real64) :: a, cx, cy, r, r0, r1
        character(len=:), allocatable :: f
        select case (s%kind)
        case (SEG_TRAVEL)
            call up(st, text)
            call block(st, text, 'G00 X' // c3(s%x1) // ' Y' // c3(s%y1))
        case (SEG_RAISE)
            call up(st, text)
        case (SEG_DOT)
            call down(st, text)
        case (SEG_LINE)
            call down(st, text)
            f = feed(st, nint(LINE_SPEED))
            call block(st, text, 'G01 X' // c3(s%x1) // ' Y' // c3(s%y1) // f)
        case (SEG_ARC)
            call down(st, text)
            if (chord_tol <= 0 .and. st%grbl .and. off_circle(s)) then
                ! the centre on the chord's bisector: both radii equal
                call bisector_centre(s, cx, cy)
                f = feed(st, nint(ARC_SPEED))
                call block(st, text, merge('G02', 'G03', s%sweep < 0) // ' X' // c3(s%x1) // &
                    ' Y' // c3(s%y1) // ' I' // fixed(cx - real(s%x0, real64) / 100, 3) // &
                    ' J' // fixed(cy - real(s%y0, real64) / 100, 3) // f)
            else if (chord_tol <= 0) then
                f = feed(st, nint(ARC_SPEED))
                call block(st, text, merge('G02', 'G03', s%sweep < 0) // ' X' // c3(s%x1) // &
                    ' Y' // c3(s%y1) // ' I' // c3(s%cx - s%x0) // ' J' // c3(s%cy - s%y0) // f)
            else
                ! The radius goes from the start's to the end's (they may differ
                ! by one unit): the chords end exactly at the tape's end point.
                r0 = s%r / 100
                r1 = hypot(real(s%x1 - s%cx, real64), real(s%y1 - s%cy, real64)) / 100
                cx = real(s%cx, real64) / 100
                cy = real(s%cy, real64) / 100
                n = chord_count(max(r0, r1), s%sweep, chord_tol)
                do j = 1, n - 1
                    a = s%a0 + s%sweep * j / n
                    r = r0 + (r1 - r0) * j / n
                    f = feed(st, nint(ARC_SPEED))
                    call block(st, text, 'G01 X' // fixed(cx + r * cos(a), 3) // ' Y' // &
                        fixed(cy + r * sin(a), 3) // f)
                end do
                f = feed(st, nint(ARC_SPEED))
                call block(st, text, 'G01 X' // c3(s%x1) // ' Y' // c3(s%y1) // f)
            end if
        end select
    end subroutine move

    !> Would GRBL find the arc's end off its circle? Its two radii differ by
    !> more than 0.004 mm (GRBL refuses 0.005 mm and 0.1 % of the radius;
    !> the margin is for its single-precision arithmetic). A full circle ends
    !> where it starts.
    logical function off_circle(s)
        type(seg_t), intent(in) :: s
        real(real64) :: r0, r1
        r0 = hypot(real(s%cx - s%x0, real64), real(s%cy - s%y0, real64)) / 100
        r1 = hypot(real(s%cx - s%x1, real64), real(s%cy - s%y1, real64)) / 100
        off_circle = abs(r1 - r0) > 0.004_real64
    end function off_circle

    !> The point of the perpendicular bisector of the arc's chord nearest its
    !> tape centre (mm), rounded to 0.001 mm: equally far from both ends
    !> within the rounding.
    subroutine bisector_centre(s, cx, cy)
        type(seg_t), intent(in) :: s
        real(real64), intent(out) :: cx, cy
        real(real64) :: mx, my, ux, uy, len2, t
        mx = real(s%x0 + s%x1, real64) / 200
        my = real(s%y0 + s%y1, real64) / 200
        ! the bisector's direction: the chord turned a quarter
        ux = -real(s%y1 - s%y0, real64) / 100
        uy = real(s%x1 - s%x0, real64) / 100
        len2 = ux * ux + uy * uy
        t = ((real(s%cx, real64) / 100 - mx) * ux + (real(s%cy, real64) / 100 - my) * uy) / len2
        cx = anint((mx + t * ux) * 1000) / 1000
        cy = anint((my + t * uy) * 1000) / 1000
    end subroutine bisector_centre

    !> " F<f>" when the feed changes, else "".
    function feed(st, f) result(s)
        type(state_t), intent(inout) :: st
        integer, intent(in) :: f
        character(len=:), allocatable :: s
        s = ''
        if (st%feed /= f) s = ' F' // str(f)
        st%feed = f
    end function feed

    subroutine down(st, text)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        character(len=:), allocatable :: f
        if (st%down) return
        if (st%use_z) then
            f = feed(st, nint(LINE_SPEED))
            call block(st, text, 'G01 Z' // Z_DOWN // f)
        else
            call block(st, text, 'M03')
        end if
        st%down = .true.
    end subroutine down

    subroutine up(st, text)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        if (.not. st%down) return
        if (st%use_z) then
            call block(st, text, 'G00 Z' // Z_UP)
        else
            call block(st, text, 'M05')
        end if
        st%down = .false.
    end subroutine up

    subroutine block(st, text, words)
        type(state_t), intent(inout) :: st
        type(text_t), intent(inout) :: text
        character(len=*), intent(in) :: words
        st%n = st%n + 1
        if (st%n > 99999) st%n = 1
        call text%add('N' // str(st%n) // ' ' // words)
    end subroutine block

    !> Units (0.01 mm) as millimetres with three decimals.
    function c3(units) result(s)
        integer(int64), intent(in) :: units
        character(len=:), allocatable :: s
        s = mm(units) // '0'
    end function c3

    !> A comment's text in characters that both ISO and EIA tape have (letters,
    !> digits, space and . , - + /), so that `em703 punch` takes the program in
    !> either code; any other character becomes "-".
    function clean(s) result(t)
        character(len=*), intent(in) :: s
        character(len=len(s)) :: t
        integer :: i
        t = s
        do i = 1, len(t)
            select case (t(i:i))
            case ('a':'z', 'A':'Z', '0':'9', ' ', '.', ',', '-', '+', '/')
            case default
                t(i:i) = '-'
            end select
        end do
    end function clean

end module em703_gcode
