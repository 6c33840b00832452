!> SVG drawings of simulated runs: one tape (strokes with the tool's width,
!> travel dashed) or a whole job (one colour per tape), on a millimetre grid.
!>
!> Coordinates are millimetres from the start point, x to the right and y up
!> (SVG's y is negated). The tool is round: a stroke is drawn with the tool's
!> width, round caps and joins, so it covers what the tool covers; a dot is a
!> disc of the tool's width. Output is plain text with fixed decimals, the same
!> bytes on every run.
module em703_svg
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use em703_sim, only: run_t, seg_t, walker_t, walk_start, next_seg, SEG_LINE, SEG_TRAVEL, SEG_ARC, SEG_DOT, PI, TWO_PI
    use base_text, only: text_t, fixed, mm
    use base_error, only: error_t
    implicit none
    private
    public :: svg_run, svg_job

    character(len=7), parameter :: LAYER_COLOUR(3) = ['#c0392b', '#1f5fa8', '#1e8449']

contains

    !> One tape: strokes in black with the tool's width (units), travel dashed.
    subroutine svg_run(run, tool, title, text)
        type(run_t), intent(in) :: run
        integer(int64), intent(in) :: tool
        character(len=*), intent(in) :: title
        type(text_t), intent(inout) :: text
        real(real64) :: box(4), thin
        box = [run%xmin, run%xmax, run%ymin, run%ymax]
        call begin(text, box, real(tool, real64) / 100, title, thin)
        call text%add('<g id="travel" fill="none" stroke="#808080" stroke-width="' // &
                      fixed(thin, 3) // '" stroke-dasharray="' // fixed(4 * thin, 3) // ' ' // &
                      fixed(3 * thin, 3) // '">')
        call segments(text, run, .true.)
        call text%add('</g>')
        call text%add('<g id="tool-down" fill="none" stroke="#1a1a1a" stroke-width="' // &
                      mm(tool) // '" stroke-linecap="round" stroke-linejoin="round">')
        call segments(text, run, .false., tool, '#1a1a1a')
        call text%add('</g>')
        call start_mark(text, thin)
        call text%add('</svg>')
    end subroutine svg_run

    !> A job: the tapes' strokes, one colour per tape (small red, large blue,
    !> cond green), each with its tool; travel is not drawn.
    subroutine svg_job(runs, tools, keys, title, text)
        type(run_t), intent(in) :: runs(:)
        integer(int64), intent(in) :: tools(:)
        character(len=*), intent(in) :: keys(:)
        character(len=*), intent(in) :: title
        type(text_t), intent(inout) :: text
        real(real64) :: box(4), thin
        integer :: l
        box = [runs(1)%xmin, runs(1)%xmax, runs(1)%ymin, runs(1)%ymax]
        do l = 2, size(runs)
            box = [min(box(1), runs(l)%xmin), max(box(2), runs(l)%xmax), &
                   min(box(3), runs(l)%ymin), max(box(4), runs(l)%ymax)]
        end do
        call begin(text, box, real(maxval(tools), real64) / 100, title, thin)
        do l = 1, size(runs)
            call text%add('<g id="' // trim(keys(l)) // '" fill="none" stroke="' // &
                LAYER_COLOUR(1 + mod(l - 1, 3)) // '" stroke-width="' // mm(tools(l)) // &
                '" stroke-linecap="round" stroke-linejoin="round" opacity="0.85">')
            call segments(text, runs(l), .false., tools(l), LAYER_COLOUR(1 + mod(l - 1, 3)))
            call text%add('</g>')
        end do
        call start_mark(text, thin)
        call text%add('</svg>')
    end subroutine svg_job

    !> The header, the view box (box in mm, grown by the tool and a margin)
    !> and the grid; thin is the width of hairlines (mm) for what follows.
    subroutine begin(text, box, tool_mm, title, thin)
        type(text_t), intent(inout) :: text
        real(real64), intent(in) :: box(4), tool_mm
        character(len=*), intent(in) :: title
        real(real64), intent(out) :: thin
        real(real64) :: x0, x1, y0, y1, extent, step, g
        integer(int64) :: i, i0, i1
        integer :: k
        real(real64), parameter :: mult(3) = [1, 2, 5]
        extent = max(box(2) - box(1), box(4) - box(3), 1.0_real64)
        g = tool_mm / 2 + max(1.0_real64, 0.05_real64 * extent)
        x0 = real(floor(box(1) - g, int64), real64)
        x1 = real(ceiling(box(2) + g, int64), real64)
        y0 = real(floor(box(3) - g, int64), real64)
        y1 = real(ceiling(box(4) + g, int64), real64)
        extent = max(x1 - x0, y1 - y0)
        thin = max(extent / 1500, 0.01_real64)
        ! 1, 2, 5, 10, 20, 50 ... mm: the finest step with at most 120 lines
        step = 1
        k = 0
        do while (extent / step > 120)
            k = k + 1
            step = mult(mod(k, 3) + 1) * 10.0_real64 ** (k / 3)
        end do
        call text%add('<?xml version="1.0" encoding="UTF-8"?>')
        call text%add('<svg xmlns="http://www.w3.org/2000/svg" width="' // fixed(x1 - x0, 0) // &
            'mm" height="' // fixed(y1 - y0, 0) // 'mm" viewBox="' // fixed(x0, 0) // ' ' // &
            fixed(-y1, 0) // ' ' // fixed(x1 - x0, 0) // ' ' // fixed(y1 - y0, 0) // '">')
        call text%add('<title>' // escape(title) // '</title>')
        call text%add('<rect x="' // fixed(x0, 0) // '" y="' // fixed(-y1, 0) // '" width="' // &
            fixed(x1 - x0, 0) // '" height="' // fixed(y1 - y0, 0) // '" fill="#ffffff"/>')
        ! The grid: a line every `step` mm, a darker one and a label every 10.
        call text%add('<g id="grid" fill="none" stroke="#d8d8d8" stroke-width="' // &
                      fixed(thin, 3) // '">')
        i0 = ceiling(x0 / step, int64)
        i1 = floor(x1 / step, int64)
        do i = i0, i1
            if (mod(i, 10_int64) == 0) cycle
            call text%add('<line x1="' // fixed(i * step, 0) // '" y1="' // fixed(-y1, 0) // &
                '" x2="' // fixed(i * step, 0) // '" y2="' // fixed(-y0, 0) // '"/>')
        end do
        i0 = ceiling(y0 / step, int64)
        i1 = floor(y1 / step, int64)
        do i = i0, i1
            if (mod(i, 10_int64) == 0) cycle
            call text%add('<line x1="' // fixed(x0, 0) // '" y1="' // fixed(-i * step, 0) // &
                '" x2="' // fixed(x1, 0) // '" y2="' // fixed(-i * step, 0) // '"/>')
        end do
        call text%add('</g>')
        call text%add('<g id="grid-10" fill="none" stroke="#a8a8a8" stroke-width="' // &
                      fixed(2 * thin, 3) // '">')
        do i = ceiling(x0 / (10 * step), int64), floor(x1 / (10 * step), int64)
            call text%add('<line x1="' // fixed(i * 10 * step, 0) // '" y1="' // fixed(-y1, 0) // &
                '" x2="' // fixed(i * 10 * step, 0) // '" y2="' // fixed(-y0, 0) // '"/>')
        end do
        do i = ceiling(y0 / (10 * step), int64), floor(y1 / (10 * step), int64)
            call text%add('<line x1="' // fixed(x0, 0) // '" y1="' // fixed(-i * 10 * step, 0) // &
                '" x2="' // fixed(x1, 0) // '" y2="' // fixed(-i * 10 * step, 0) // '"/>')
        end do
        call text%add('</g>')
        call text%add('<g id="grid-labels" fill="#808080" font-family="sans-serif" font-size="' // &
                      fixed(40 * thin, 3) // '">')
        do i = ceiling(x0 / (10 * step), int64), floor(x1 / (10 * step), int64)
            call text%add('<text x="' // fixed(i * 10 * step + thin * 10, 3) // '" y="' // &
                fixed(-y0 - thin * 10, 3) // '">' // fixed(i * 10 * step, 0) // '</text>')
        end do
        do i = ceiling(y0 / (10 * step), int64), floor(y1 / (10 * step), int64)
            call text%add('<text x="' // fixed(x0 + thin * 10, 3) // '" y="' // &
                fixed(-i * 10 * step - thin * 10, 3) // '">' // fixed(i * 10 * step, 0) // '</text>')
        end do
        call text%add('</g>')
    end subroutine begin

    !> A small cross at the start point.
    subroutine start_mark(text, thin)
        type(text_t), intent(inout) :: text
        real(real64), intent(in) :: thin
        character(len=:), allocatable :: a
        a = fixed(15 * thin, 3)
        call text%add('<path id="start" d="M -' // a // ' 0 H ' // a // ' M 0 -' // a // ' V ' // &
            a // '" stroke="#e67e22" stroke-width="' // fixed(2 * thin, 3) // '" fill="none"/>')
    end subroutine start_mark

    !> The segments of a run: travel (travel = .true.) or what the tool draws
    !> (lines, arcs, circles; dots as discs of the tool's width in colour).
    subroutine segments(text, run, travel, tool, colour)
        type(text_t), intent(inout) :: text
        type(run_t), intent(in) :: run
        logical, intent(in) :: travel
        integer(int64), intent(in), optional :: tool
        character(len=*), intent(in), optional :: colour
        type(seg_t) :: s
        type(walker_t) :: w
        type(error_t), allocatable :: err
        logical :: got
        character(len=:), allocatable :: flags
        call walk_start(w, run, err)
        if (allocated(err)) return
        do
            call next_seg(w, run, s, got)
            if (.not. got) exit
            select case (s%kind)
            case (SEG_TRAVEL)
                if (travel) call text%add('<line x1="' // mm(s%x0) // '" y1="' // mm(-s%y0) // &
                    '" x2="' // mm(s%x1) // '" y2="' // mm(-s%y1) // '"/>')
            case (SEG_LINE)
                if (.not. travel) call text%add('<line x1="' // mm(s%x0) // '" y1="' // &
                    mm(-s%y0) // '" x2="' // mm(s%x1) // '" y2="' // mm(-s%y1) // '"/>')
            case (SEG_ARC)
                if (travel) cycle
                if (abs(s%sweep) >= TWO_PI - 1.0e-12_real64) then
                    call text%add('<circle cx="' // mm(s%cx) // '" cy="' // mm(-s%cy) // &
                                  '" r="' // fixed(s%r / 100, 4) // '"/>')
                else
                    ! y is negated: a clockwise arc (sweep < 0) has SVG sweep-flag 1.
                    flags = merge('1', '0', abs(s%sweep) > PI) // ' ' // merge('1', '0', s%sweep < 0)
                    call text%add('<path d="M ' // mm(s%x0) // ' ' // mm(-s%y0) // ' A ' // &
                        fixed(s%r / 100, 4) // ' ' // fixed(s%r / 100, 4) // ' 0 ' // flags // ' ' // &
                        mm(s%x1) // ' ' // mm(-s%y1) // '"/>')
                end if
            case (SEG_DOT)
                if (travel) cycle
                call text%add('<circle cx="' // mm(s%x0) // '" cy="' // mm(-s%y0) // '" r="' // &
                    fixed(real(tool, real64) / 200, 3) // '" fill="' // colour // '" stroke="none"/>')
            end select
        end do
    end subroutine segments

    !> Text for XML: & < > " escaped.
    function escape(s) result(t)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: t
        integer :: i
        t = ''
        do i = 1, len(s)
            select case (s(i:i))
            case ('&'); t = t // '&amp;'
            case ('<'); t = t // '&lt;'
            case ('>'); t = t // '&gt;'
            case ('"'); t = t // '&quot;'
            case default; t = t // s(i:i)
            end select
        end do
    end function escape

end module em703_svg
