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
    use em703_codec, only: frame_t, decoder_t, decoder_start, next_frame
    use base_error, only: error_t, new_error, AT_ROW, no_memory
    use base_text, only: str, fixed, mm
    implicit none
    private
    public :: seg_t, run_t, walker_t, simulate, simulate_image, walk_start, next_seg, &
              run_segments, arc_sweep, arc_extent, field_check, seg_box, shift_run

    !> Speeds of the report's machine, mm/min; the field, mm.
    real(real64), parameter, public :: LINE_SPEED = 5500.0_real64, ARC_SPEED = 1500.0_real64, &
                                       TRAVEL_SPEED = 5500.0_real64
    real(real64), parameter, public :: FIELD_MM = 1200.0_real64
    !> The same field in units of 0.01 mm (the job sheet's and sim --start's range).
    integer(int64), parameter, public :: FIELD_UNITS = nint(FIELD_MM * 100, int64)
    real(real64), parameter, public :: PI = 3.14159265358979323846_real64, TWO_PI = 2 * PI
    !> Kinds of segments: a drawn line, a move with the tool raised, an arc or
    !> circle, a dot, and a raise without a move (K20 alone).
    integer, parameter, public :: SEG_LINE = 1, SEG_TRAVEL = 2, SEG_ARC = 3, SEG_DOT = 4, &
                                  SEG_RAISE = 5

    !> Executed frames that svg, gcode and gerber write one by one: past this,
    !> a drawing or program would run to gigabytes (a tape of 10^6 pads in
    !> rows runs about 2 * 10^6). The simulation itself has no limit.
    integer(int64), parameter, public :: MAX_DRAWN = 10000000_int64

    !> One executed move. Lines, travel: (x0, y0) -> (x1, y1). Arcs: centre
    !> (cx, cy), radius r, start angle a0, signed sweep (|sweep| = 2 pi for a
    !> circle), from (x0, y0) to (x1, y1). frame: the tape frame (1-based),
    !> row: the row of its first code.
    type :: seg_t
        integer :: kind = SEG_LINE
        integer(int64) :: x0 = 0, y0 = 0, x1 = 0, y1 = 0
        integer(int64) :: cx = 0, cy = 0
        real(real64) :: r = 0, a0 = 0, sweep = 0
        integer :: frame = 0
        integer :: row = 0
    end type seg_t

    !> A run of a tape: where its frames come from, and what running them
    !> gives. The frames are never held for a tape image: bytes is the image
    !> (a byte a row), decoded again whenever the segments are walked
    !> (walk_start, next_seg); a run made from frames (simulate) keeps them.
    !> The statistics: frames executed (cycles unrolled), the end point and
    !> tool state, lengths (mm), minutes, the box of the tool centre over the
    !> whole path (mm; start point, travel and arc extremes included). A run
    !> moved by shift_run starts at (ox, oy) units.
    type :: run_t
        character(len=:), allocatable :: bytes
        character(len=1) :: code = '8'
        logical :: told = .false.
        integer :: evidence = 0          !< decoder_t's: the row that told the variant
        type(frame_t), allocatable :: frames(:)
        integer :: nrows = 0
        integer :: nframes = 0
        integer(int64) :: ox = 0, oy = 0
        integer(int64) :: executed = 0
        integer :: long_row = 0          !< row where executed passes MAX_DRAWN (0: never)
        integer(int64) :: end_x = 0, end_y = 0
        logical :: down = .false.
        real(real64) :: line_mm = 0, arc_mm = 0, travel_mm = 0, drawn_mm = 0, minutes = 0
        real(real64) :: xmin = 0, xmax = 0, ymin = 0, ymax = 0
    end type run_t

    !> A step of a run: one frame (nseg = 1, reps = 1) or a cycle pair run
    !> reps times (nseg = 2), each pass moving the tool by (dx, dy).
    type :: step_t
        integer :: nseg = 1
        type(seg_t) :: segs(2)
        integer(int64) :: reps = 1
        integer(int64) :: dx = 0, dy = 0
    end type step_t

    !> Walking a run's segments in execution order (walk_start, next_seg):
    !> the frames one step at a time, a cycle pair unrolled as it is walked.
    type :: walker_t
        type(decoder_t) :: dec
        integer :: next = 1                  !< next frame of run%frames
        integer :: frame = 0                 !< frames taken so far
        integer(int64) :: px = 0, py = 0     !< the tool after the steps taken
        type(step_t) :: step
        integer(int64) :: rep = 0            !< the pass of step being walked
        integer :: j = 0                     !< its segment
        logical :: started = .false.
    end type walker_t

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

    !> Run frames from (0, 0) with the tool raised (the frames are kept in
    !> the run). The frames are those of a decoded tape (the decoder checked
    !> each frame); err names the row of a CYC without a following frame.
    subroutine simulate(frames, run, err)
        type(frame_t), intent(in) :: frames(:)
        type(run_t), intent(out) :: run
        type(error_t), allocatable, intent(out) :: err
        integer :: st
        allocate(run%frames(size(frames)), stat=st)
        if (st /= 0) call no_memory('the frames of the run', &
            int(size(frames), int64) * storage_size(frames) / 8)
        run%frames = frames
        run%told = .true.
        call run_stats(run, err)
    end subroutine simulate

    !> Run a tape image (bytes 0..255, a byte a row; code "8", "K" or
    !> "auto", as decode_tape) from (0, 0) with the tool raised, decoding it
    !> frame by frame: the run takes the bytes over (data is left
    !> unallocated), and no frame is kept. err: the decoder's first error.
    subroutine simulate_image(data, code, run, err)
        character(len=:), allocatable, intent(inout) :: data
        character(len=*), intent(in) :: code
        type(run_t), intent(out) :: run
        type(error_t), allocatable, intent(out) :: err
        type(decoder_t) :: dec
        call move_alloc(data, run%bytes)
        run%nrows = len(run%bytes)
        ! the variant, told once: every later walk reads in it
        call decoder_start(dec, run%bytes, code, err)
        run%code = dec%code
        run%told = dec%told
        run%evidence = dec%evidence
        if (allocated(err)) return
        call run_stats(run, err)
    end subroutine simulate_image

    !> The statistics of a run, one step at a time: a cycle pair counts its
    !> passes at once (each pass is the first moved by a whole number of
    !> displacements), so a tape of any length and any cycle counts runs in
    !> the time of its frames.
    subroutine run_stats(run, err)
        type(run_t), intent(inout) :: run
        type(error_t), allocatable, intent(out) :: err
        type(walker_t) :: w
        logical :: got
        integer :: j
        real(real64) :: line_len, arc_len, travel_len, box(4), reach(2)
        type(seg_t) :: s
        run%ox = 0
        run%oy = 0
        line_len = 0
        arc_len = 0
        travel_len = 0
        run%xmin = 0
        run%xmax = 0
        run%ymin = 0
        run%ymax = 0
        call walk_start(w, run, err)
        if (allocated(err)) return
        do
            call next_step(w, run, got, err)
            if (allocated(err) .or. .not. got) exit
            do j = 1, w%step%nseg
                s = w%step%segs(j)
                select case (s%kind)
                case (SEG_LINE)
                    line_len = line_len + w%step%reps * seg_length(s)
                case (SEG_TRAVEL)
                    travel_len = travel_len + w%step%reps * seg_length(s)
                case (SEG_ARC)
                    arc_len = arc_len + w%step%reps * (s%r * abs(s%sweep))
                end select
                call seg_box(s, box)
                call grow(box)
                if (w%step%reps > 1) then
                    reach = real(w%step%reps - 1, real64) * [real(w%step%dx, real64), &
                                                             real(w%step%dy, real64)]
                    call grow([box(1) + reach(1), box(2) + reach(1), box(3) + reach(2), &
                               box(4) + reach(2)])
                end if
            end do
            run%executed = run%executed + w%step%nseg * w%step%reps
            if (run%long_row == 0 .and. run%executed > MAX_DRAWN) run%long_row = w%step%segs(1)%row
            run%down = .not. any(w%step%segs(w%step%nseg)%kind == [SEG_TRAVEL, SEG_RAISE])
        end do
        run%nframes = w%frame
        if (allocated(err)) return
        run%end_x = w%px
        run%end_y = w%py
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
        subroutine grow(b)
            real(real64), intent(in) :: b(4)
            run%xmin = min(run%xmin, b(1))
            run%xmax = max(run%xmax, b(2))
            run%ymin = min(run%ymin, b(3))
            run%ymax = max(run%ymax, b(4))
        end subroutine grow
    end subroutine run_stats

    !> Start walking a run from its start point (the origin, or where
    !> shift_run moved it).
    subroutine walk_start(w, run, err)
        type(walker_t), intent(out) :: w
        type(run_t), intent(in) :: run
        type(error_t), allocatable, intent(out) :: err
        w%px = run%ox
        w%py = run%oy
        w%started = .true.
        if (allocated(run%bytes)) call decoder_start(w%dec, run%bytes, run%code, err, &
                                                     run%evidence)
    end subroutine walk_start

    !> The run's next frame; got = .false. at its end.
    subroutine next_source_frame(w, run, f, got, err)
        type(walker_t), intent(inout) :: w
        type(run_t), intent(in) :: run
        type(frame_t), intent(out) :: f
        logical, intent(out) :: got
        type(error_t), allocatable, intent(out) :: err
        if (allocated(run%bytes)) then
            call next_frame(w%dec, run%bytes, f, got, err)
        else
            got = .false.
            if (.not. allocated(run%frames)) return
            got = w%next <= size(run%frames)
            if (got) f = run%frames(w%next)
            w%next = w%next + 1
        end if
        if (got) w%frame = w%frame + 1
    end subroutine next_source_frame

    !> The next step of a run (w%step): a frame, or a cycle pair with its
    !> count; the tool's place moves past all of its passes.
    subroutine next_step(w, run, got, err)
        type(walker_t), intent(inout) :: w
        type(run_t), intent(in) :: run
        logical, intent(out) :: got
        type(error_t), allocatable, intent(out) :: err
        type(frame_t) :: f, g
        logical :: more
        call next_source_frame(w, run, f, got, err)
        if (allocated(err) .or. .not. got) then
            got = .false.
            return
        end if
        w%step%reps = 1
        w%step%nseg = 1
        call frame_seg(f, w%px, w%py, w%frame, w%step%segs(1))
        if (f%cyc /= 0) then
            more = .false.
            if (f%cyc >= 2) call next_source_frame(w, run, g, more, err)
            if (allocated(err)) then
                got = .false.
                return
            end if
            if (.not. more) then
                call new_error(err, 'frame ' // str(w%frame) // ': CYC needs a following frame ' // &
                               'and at least 2 runs', AT_ROW, f%row)
                got = .false.
                return
            end if
            w%step%nseg = 2
            w%step%reps = f%cyc
            call frame_seg(g, w%step%segs(1)%x1, w%step%segs(1)%y1, w%frame, w%step%segs(2))
        end if
        w%step%dx = w%step%segs(w%step%nseg)%x1 - w%px
        w%step%dy = w%step%segs(w%step%nseg)%y1 - w%py
        w%px = w%px + w%step%reps * w%step%dx
        w%py = w%py + w%step%reps * w%step%dy
    end subroutine next_step

    !> The next executed segment of a run (cycles unrolled); got = .false.
    !> at its end. A run that was simulated walks without an error.
    subroutine next_seg(w, run, s, got)
        type(walker_t), intent(inout) :: w
        type(run_t), intent(in) :: run
        type(seg_t), intent(out) :: s
        logical, intent(out) :: got
        type(error_t), allocatable :: err
        integer(int64) :: tx, ty
        got = .true.
        if (w%rep == 0 .or. (w%rep >= w%step%reps .and. w%j >= w%step%nseg)) then
            call next_step(w, run, got, err)
            if (.not. got) return
            w%rep = 1
            w%j = 0
        end if
        w%j = w%j + 1
        if (w%j > w%step%nseg) then
            w%j = 1
            w%rep = w%rep + 1
        end if
        s = w%step%segs(w%j)
        tx = (w%rep - 1) * w%step%dx
        ty = (w%rep - 1) * w%step%dy
        s%x0 = s%x0 + tx
        s%x1 = s%x1 + tx
        s%cx = s%cx + tx
        s%y0 = s%y0 + ty
        s%y1 = s%y1 + ty
        s%cy = s%cy + ty
    end subroutine next_seg

    !> Every executed segment of a run, in order (for small runs: a test, a
    !> picture of a few frames).
    subroutine run_segments(run, segs, n)
        type(run_t), intent(in) :: run
        type(seg_t), allocatable, intent(out) :: segs(:)
        integer, intent(out) :: n
        type(walker_t) :: w
        type(error_t), allocatable :: err
        type(seg_t) :: s
        logical :: got
        integer :: st
        allocate(segs(max(1_int64, run%executed)), stat=st)
        if (st /= 0) call no_memory('the segments of the run', &
            run%executed * storage_size(s) / 8)
        n = 0
        call walk_start(w, run, err)
        if (allocated(err)) return
        do
            call next_seg(w, run, s, got)
            if (.not. got .or. n == size(segs)) exit
            n = n + 1
            segs(n) = s
        end do
    end subroutine run_segments

    !> The segment frame f executes from (px, py); number: the frame's number.
    subroutine frame_seg(f, px, py, number, s)
        type(frame_t), intent(in) :: f
        integer(int64), intent(in) :: px, py
        integer, intent(in) :: number
        type(seg_t), intent(out) :: s
        s%frame = number
        s%row = f%row
        s%x0 = px
        s%y0 = py
        if (f%k == 10 .or. f%k == 20) then
            s%x1 = px + f%dx
            s%y1 = py + f%dy
            if (f%k == 10) then
                s%kind = merge(SEG_LINE, SEG_DOT, f%dx /= 0 .or. f%dy /= 0)
            else
                s%kind = merge(SEG_TRAVEL, SEG_RAISE, f%dx /= 0 .or. f%dy /= 0)
            end if
        else
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
        end if
    end subroutine frame_seg

    real(real64) function seg_length(s)
        type(seg_t), intent(in) :: s
        seg_length = hypot(real(s%x1 - s%x0, real64), real(s%y1 - s%y0, real64))
    end function seg_length

    !> Does the run stay on the field (0..1200 mm on both axes) with the start
    !> point at (start_x, start_y) units of the field and the machine at scale
    !> num:den? If not, err names the row of the first frame that leaves, and
    !> where the carriage would go. The start point itself must be on the field.
    !> A cycle pair's passes are the first pass moved step by step: the first
    !> pass that leaves is found by bisection (once a pass is off the field on
    !> one side, every later pass is further off on that side).
    subroutine field_check(run, start_x, start_y, num, den, err)
        type(run_t), intent(in) :: run
        integer(int64), intent(in) :: start_x, start_y
        integer, intent(in) :: num, den
        type(error_t), allocatable, intent(out) :: err
        real(real64) :: boxes(4, 2), s, limit
        type(walker_t) :: w
        type(error_t), allocatable :: werr
        logical :: got
        integer :: j, first_j
        integer(int64) :: lo_k, hi_k, mid, first_k
        character(len=:), allocatable :: what
        s = real(num, real64) / real(den, real64)
        limit = FIELD_MM * 100
        call walk_start(w, run, werr)
        if (allocated(werr)) return
        do
            call next_step(w, run, got, werr)
            if (.not. got) return
            do j = 1, w%step%nseg
                call seg_box(w%step%segs(j), boxes(:, j))
            end do
            first_k = 0
            first_j = 0
            do j = 1, w%step%nseg
                if (.not. leaves(j, w%step%reps)) cycle
                if (leaves(j, 1_int64)) then
                    lo_k = 1
                else
                    ! leaves(j, lo_k) is false, leaves(j, hi_k) true
                    lo_k = 1
                    hi_k = w%step%reps
                    do while (hi_k - lo_k > 1)
                        mid = lo_k + (hi_k - lo_k) / 2
                        if (leaves(j, mid)) then
                            hi_k = mid
                        else
                            lo_k = mid
                        end if
                    end do
                    lo_k = hi_k
                end if
                if (first_k == 0 .or. lo_k < first_k) then
                    first_k = lo_k
                    first_j = j
                end if
            end do
            if (first_k > 0) then
                what = where_off(first_j, first_k)
                call new_error(err, 'frame ' // str(w%step%segs(first_j)%frame) // &
                    ' leaves the field (0..1200 mm) at scale ' // str(num) // ':' // str(den) // &
                    ' from the start point (' // mm(start_x) // ', ' // mm(start_y) // &
                    ') mm: the carriage reaches ' // what, AT_ROW, w%step%segs(first_j)%row)
                return
            end if
        end do
    contains
        !> The field's corners reached by segment j in pass k (units).
        subroutine corners(j, k, lo, hi)
            integer, intent(in) :: j
            integer(int64), intent(in) :: k
            real(real64), intent(out) :: lo(2), hi(2)
            real(real64) :: tx, ty
            tx = real(k - 1, real64) * real(w%step%dx, real64)
            ty = real(k - 1, real64) * real(w%step%dy, real64)
            lo = [start_x + (boxes(1, j) + tx) * s, start_y + (boxes(3, j) + ty) * s]
            hi = [start_x + (boxes(2, j) + tx) * s, start_y + (boxes(4, j) + ty) * s]
        end subroutine corners
        logical function leaves(j, k)
            integer, intent(in) :: j
            integer(int64), intent(in) :: k
            real(real64) :: lo(2), hi(2)
            call corners(j, k, lo, hi)
            leaves = any(lo < -1.0e-6_real64) .or. any(hi > limit + 1.0e-6_real64)
        end function leaves
        function where_off(j, k) result(t)
            integer, intent(in) :: j
            integer(int64), intent(in) :: k
            character(len=:), allocatable :: t
            real(real64) :: lo(2), hi(2)
            call corners(j, k, lo, hi)
            if (lo(1) < -1.0e-6_real64) then
                t = 'x = ' // fixed(lo(1) / 100, 2) // ' mm'
            else if (lo(2) < -1.0e-6_real64) then
                t = 'y = ' // fixed(lo(2) / 100, 2) // ' mm'
            else if (hi(1) > limit + 1.0e-6_real64) then
                t = 'x = ' // fixed(hi(1) / 100, 2) // ' mm'
            else
                t = 'y = ' // fixed(hi(2) / 100, 2) // ' mm'
            end if
        end function where_off
    end subroutine field_check

    !> Move a run by (dx, dy) units: a tape that starts where another ended.
    subroutine shift_run(run, dx, dy)
        type(run_t), intent(inout) :: run
        integer(int64), intent(in) :: dx, dy
        if (dx == 0 .and. dy == 0) return
        run%ox = run%ox + dx
        run%oy = run%oy + dy
        run%end_x = run%end_x + dx
        run%end_y = run%end_y + dy
        run%xmin = run%xmin + real(dx, real64) / 100
        run%xmax = run%xmax + real(dx, real64) / 100
        run%ymin = run%ymin + real(dy, real64) / 100
        run%ymax = run%ymax + real(dy, real64) / 100
    end subroutine shift_run

end module em703_sim
