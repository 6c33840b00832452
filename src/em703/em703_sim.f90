!> The EM-703 coordinatograph, simulated frame by frame.
!>
!> Source: the report's "Описание координатографа" and "Состав кадра"
!> (docs/TAPE.md). Positions are integers in tape units (0.01 mm) relative to
!> the start point; lengths and the bounding box come out in millimetres.
!>
!> * The tool starts raised at (0, 0).
!> * K10 lowers the tool and draws a straight line by (DX, DY); without DX, DY
!>   it is a dot (the tool lowered where it stands).
!> * K20 raises the tool and moves by (DX, DY) (travel).
!> * K11 / K13 lower the tool and draw a circle (no DX, DY) or an arc ending at
!>   position + (DX, DY); (X, Y) is the tool relative to the centre. K13 is the
!>   + direction, clockwise; K11 the - direction, counter-clockwise.
!> * CYC n on a frame: it and the next frame run n times in all.
!> Angles are mathematical (radians from +X, positive counter-clockwise), so a
!> K13 arc has a negative sweep.
module em703_sim
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use em703_codec, only: frame_t
    use base_error, only: error_t, new_error, AT_ROW, no_memory
    use base_text, only: str, fixed, mm
    implicit none
    private
    public :: seg_t, run_t, simulate, arc_sweep, arc_extent, field_check, seg_box, shift_run

    !> Speeds of the report's machine, mm/min; the field, mm; the executed-frame limit.
    real(real64), parameter, public :: LINE_SPEED = 5500.0_real64, ARC_SPEED = 1500.0_real64, &
                                       TRAVEL_SPEED = 5500.0_real64
    real(real64), parameter, public :: FIELD_MM = 1200.0_real64
    integer, parameter, public :: MAX_EXECUTED = 1000000
    real(real64), parameter, public :: PI = 3.14159265358979323846_real64, TWO_PI = 2 * PI
    !> Kinds of segments: a drawn line, a move with the tool raised, an arc or
    !> circle, a dot, and a raise without a move (K20 alone).
    integer, parameter, public :: SEG_LINE = 1, SEG_TRAVEL = 2, SEG_ARC = 3, SEG_DOT = 4, &
                                  SEG_RAISE = 5

    !> One executed move. Lines, travel: (x0, y0) -> (x1, y1). Arcs: centre
    !> (cx, cy), radius r, start angle a0, signed sweep (|sweep| = 2 pi for a
    !> circle), from (x0, y0) to (x1, y1). frame: the tape frame (1-based).
    type :: seg_t
        integer :: kind = SEG_LINE
        integer(int64) :: x0 = 0, y0 = 0, x1 = 0, y1 = 0
        integer(int64) :: cx = 0, cy = 0
        real(real64) :: r = 0, a0 = 0, sweep = 0
        integer :: frame = 0
    end type seg_t

    !> The result of a run: the segments in execution order, the end point and
    !> tool state, lengths (mm), minutes, the box of the tool centre over the
    !> whole path (mm; start point, travel and arc extremes included).
    type :: run_t
        type(seg_t), allocatable :: segs(:)
        integer :: nseg = 0
        integer :: executed = 0
        integer(int64) :: end_x = 0, end_y = 0
        logical :: down = .false.
        real(real64) :: line_mm = 0, arc_mm = 0, travel_mm = 0, drawn_mm = 0, minutes = 0
        real(real64) :: xmin = 0, xmax = 0, ymin = 0, ymax = 0
    end type run_t

contains

    !> Signed sweep from direction (x0, y0) to direction (x1, y1) turning
    !> clockwise (negative) or counter-clockwise; equal directions: a full turn.
    real(real64) function arc_sweep(x0, y0, x1, y1, clockwise) result(sweep)
        real(real64), intent(in) :: x0, y0, x1, y1
        logical, intent(in) :: clockwise
        real(real64) :: a0, a1, turn
        a0 = atan2(y0, x0)
        a1 = atan2(y1, x1)
        if (clockwise) then
            turn = modulo(a0 - a1, TWO_PI)
        else
            turn = modulo(a1 - a0, TWO_PI)
        end if
        if (turn <= 1.0e-12_real64) turn = TWO_PI
        sweep = merge(-turn, turn, clockwise)
    end function arc_sweep

    !> Box (xmin, xmax, ymin, ymax) of an arc's centre line, in its units,
    !> with the axis extremes the arc passes through.
    subroutine arc_extent(cx, cy, r, a0, sweep, box)
        real(real64), intent(in) :: cx, cy, r, a0, sweep
        real(real64), intent(out) :: box(4)
        real(real64) :: lo, hi, ang, px, py
        integer :: q
        if (abs(sweep) >= TWO_PI - 1.0e-12_real64) then
            box = [cx - r, cx + r, cy - r, cy + r]
            return
        end if
        px = cx + r * cos(a0)
        py = cy + r * sin(a0)
        box = [px, px, py, py]
        call grow(cx + r * cos(a0 + sweep), cy + r * sin(a0 + sweep))
        lo = min(a0, a0 + sweep)
        hi = max(a0, a0 + sweep)
        do q = floor(lo / (PI / 2)), ceiling(hi / (PI / 2))
            ang = q * (PI / 2)
            if (ang >= lo - 1.0e-12_real64 .and. ang <= hi + 1.0e-12_real64) then
                call grow(cx + r * anint(cos(ang)), cy + r * anint(sin(ang)))
            end if
        end do
    contains
        subroutine grow(x, y)
            real(real64), intent(in) :: x, y
            box(1) = min(box(1), x)
            box(2) = max(box(2), x)
            box(3) = min(box(3), y)
            box(4) = max(box(4), y)
        end subroutine grow
    end subroutine arc_extent

    !> Box of one segment's tool-centre path, in units.
    subroutine seg_box(s, box)
        type(seg_t), intent(in) :: s
        real(real64), intent(out) :: box(4)
        real(real64) :: b(4)
        box = [real(min(s%x0, s%x1), real64), real(max(s%x0, s%x1), real64), &
               real(min(s%y0, s%y1), real64), real(max(s%y0, s%y1), real64)]
        if (s%kind == SEG_ARC) then
            call arc_extent(real(s%cx, real64), real(s%cy, real64), s%r, s%a0, s%sweep, b)
            box = [min(box(1), b(1)), max(box(2), b(2)), min(box(3), b(3)), max(box(4), b(4))]
        end if
    end subroutine seg_box

    !> Run the frames from (0, 0) with the tool raised. The frames are those
    !> of a decoded tape (the decoder checked each frame); err names the row of
    !> a CYC that would run more than MAX_EXECUTED frames.
    subroutine simulate(frames, run, err)
        type(frame_t), intent(in) :: frames(:)
        type(run_t), intent(out) :: run
        type(error_t), allocatable, intent(out) :: err
        integer(int64) :: total
        integer :: i, j, rep, st
        integer(int64) :: px, py
        real(real64) :: line_len, arc_len, travel_len

        ! Count the executed frames first (cycles unrolled).
        total = 0
        i = 1
        do while (i <= size(frames))
            j = i
            if (frames(i)%cyc /= 0) then
                if (frames(i)%cyc < 2 .or. i == size(frames)) then
                    call new_error(err, 'frame ' // str(i) // ': CYC needs a following frame ' // &
                                   'and at least 2 runs', AT_ROW, frames(i)%row)
                    return
                end if
                total = total + 2 * frames(i)%cyc
                i = i + 2
            else
                total = total + 1
                i = i + 1
            end if
            if (total > MAX_EXECUTED) then
                call new_error(err, 'the tape runs more than ' // str(MAX_EXECUTED) // &
                    ' frames (cycles unrolled), the limit of the simulator', AT_ROW, frames(j)%row)
                return
            end if
        end do
        allocate(run%segs(max(1, int(total))), stat=st)
        if (st /= 0) call no_memory('the simulated run (' // str(total) // ' frames)', &
            total * storage_size(run%segs(1)) / 8)
        px = 0
        py = 0
        line_len = 0
        arc_len = 0
        travel_len = 0
        i = 1
        do while (i <= size(frames))
            if (frames(i)%cyc /= 0) then
                do rep = 1, int(frames(i)%cyc)
                    call step(i)
                    call step(i + 1)
                end do
                i = i + 2
            else
                call step(i)
                i = i + 1
            end if
        end do
        run%end_x = px
        run%end_y = py
        run%line_mm = line_len / 100
        run%arc_mm = arc_len / 100
        run%travel_mm = travel_len / 100
        run%drawn_mm = (line_len + arc_len) / 100
        run%minutes = line_len / 100 / LINE_SPEED + arc_len / 100 / ARC_SPEED &
                      + travel_len / 100 / TRAVEL_SPEED
        run%xmin = run%xmin / 100
        run%xmax = run%xmax / 100
        run%ymin = run%ymin / 100
        run%ymax = run%ymax / 100
    contains
        subroutine step(j)
            integer, intent(in) :: j
            type(seg_t) :: s
            real(real64) :: box(4)
            type(frame_t) :: f
            f = frames(j)
            run%executed = run%executed + 1
            s%frame = j
            s%x0 = px
            s%y0 = py
            if (f%k == 10 .or. f%k == 20) then
                s%x1 = px + f%dx
                s%y1 = py + f%dy
                if (f%k == 10) then
                    run%down = .true.
                    if (f%dx /= 0 .or. f%dy /= 0) then
                        s%kind = SEG_LINE
                        line_len = line_len + seg_length(s)
                    else
                        s%kind = SEG_DOT
                    end if
                else
                    run%down = .false.
                    if (f%dx /= 0 .or. f%dy /= 0) then
                        s%kind = SEG_TRAVEL
                        travel_len = travel_len + seg_length(s)
                    else
                        s%kind = SEG_RAISE
                    end if
                end if
            else
                run%down = .true.
                s%kind = SEG_ARC
                s%cx = px - f%x
                s%cy = py - f%y
                s%r = hypot(real(f%x, real64), real(f%y, real64))
                s%a0 = atan2(real(f%y, real64), real(f%x, real64))
                if (f%dx /= 0 .or. f%dy /= 0) then
                    s%x1 = px + f%dx
                    s%y1 = py + f%dy
                    s%sweep = arc_sweep(real(f%x, real64), real(f%y, real64), &
                        real(s%x1 - s%cx, real64), real(s%y1 - s%cy, real64), f%k == 13)
                else
                    s%x1 = px
                    s%y1 = py
                    s%sweep = merge(-TWO_PI, TWO_PI, f%k == 13)
                end if
                arc_len = arc_len + s%r * abs(s%sweep)
            end if
            call seg_box(s, box)
            run%xmin = min(run%xmin, box(1))
            run%xmax = max(run%xmax, box(2))
            run%ymin = min(run%ymin, box(3))
            run%ymax = max(run%ymax, box(4))
            run%nseg = run%nseg + 1
            run%segs(run%nseg) = s
            px = s%x1
            py = s%y1
        end subroutine step
    end subroutine simulate

    real(real64) function seg_length(s)
        type(seg_t), intent(in) :: s
        seg_length = hypot(real(s%x1 - s%x0, real64), real(s%y1 - s%y0, real64))
    end function seg_length

    !> Does the run stay on the field (0..1200 mm on both axes) with the start
    !> point at (start_x, start_y) units of the field and the machine at scale
    !> num:den? If not, err names the row of the first frame that leaves, and
    !> where the carriage would go. The start point itself must be on the field.
    subroutine field_check(run, frames, start_x, start_y, num, den, err)
        type(run_t), intent(in) :: run
        type(frame_t), intent(in) :: frames(:)
        integer(int64), intent(in) :: start_x, start_y
        integer, intent(in) :: num, den
        type(error_t), allocatable, intent(out) :: err
        real(real64) :: box(4), lo(2), hi(2), s, limit
        integer :: i
        character(len=:), allocatable :: what
        s = real(num, real64) / real(den, real64)
        limit = FIELD_MM * 100
        do i = 1, run%nseg
            call seg_box(run%segs(i), box)
            lo = [start_x + box(1) * s, start_y + box(3) * s]
            hi = [start_x + box(2) * s, start_y + box(4) * s]
            if (any(lo < -1.0e-6_real64) .or. any(hi > limit + 1.0e-6_real64)) then
                if (lo(1) < -1.0e-6_real64) then
                    what = 'x = ' // fixed(lo(1) / 100, 2) // ' mm'
                else if (lo(2) < -1.0e-6_real64) then
                    what = 'y = ' // fixed(lo(2) / 100, 2) // ' mm'
                else if (hi(1) > limit + 1.0e-6_real64) then
                    what = 'x = ' // fixed(hi(1) / 100, 2) // ' mm'
                else
                    what = 'y = ' // fixed(hi(2) / 100, 2) // ' mm'
                end if
                call new_error(err, 'frame ' // str(run%segs(i)%frame) // &
                    ' leaves the field (0..1200 mm) at scale ' // str(num) // ':' // str(den) // &
                    ' from the start point (' // mm(start_x) // ', ' // mm(start_y) // &
                    ') mm: the carriage reaches ' // what, AT_ROW, frames(run%segs(i)%frame)%row)
                return
            end if
        end do
    end subroutine field_check

    !> Move a run by (dx, dy) units: a tape that starts where another ended.
    subroutine shift_run(run, dx, dy)
        type(run_t), intent(inout) :: run
        integer(int64), intent(in) :: dx, dy
        integer :: i
        if (dx == 0 .and. dy == 0) return
        do i = 1, run%nseg
            run%segs(i)%x0 = run%segs(i)%x0 + dx
            run%segs(i)%x1 = run%segs(i)%x1 + dx
            run%segs(i)%cx = run%segs(i)%cx + dx
            run%segs(i)%y0 = run%segs(i)%y0 + dy
            run%segs(i)%y1 = run%segs(i)%y1 + dy
            run%segs(i)%cy = run%segs(i)%cy + dy
        end do
        run%end_x = run%end_x + dx
        run%end_y = run%end_y + dy
        run%xmin = run%xmin + real(dx, real64) / 100
        run%xmax = run%xmax + real(dx, real64) / 100
        run%ymin = run%ymin + real(dy, real64) / 100
        run%ymax = run%ymax + real(dy, real64) / 100
    end subroutine shift_run

end module em703_sim
