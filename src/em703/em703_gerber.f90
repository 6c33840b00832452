!> Simulated runs as one Gerber RS-274X image: the photomask the tapes draw.
!>
!> Millimetres (%MOMM*%), absolute coordinates with leading zeros omitted
!> and 6.6 digits (%FSLAX66Y66*%), the start point as the origin, dark polarity.
!> One circular aperture per tape, its diameter the tape's tool (D10 small,
!> D11 large, D12 cond for a job). A drawn line is a D01 in linear mode (G01),
!> an arc a D01 in circular mode (G02 clockwise = K13, G03 counter-clockwise =
!> K11) with G75 (multi-quadrant, I and J the signed offset of the centre);
!> a full circle is written as two half arcs. A dot is a flash (D03). Travel
!> is a D02 move.
module em703_gerber
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use em703_sim, only: run_t, seg_t, walker_t, walk_start, next_seg, SEG_LINE, SEG_TRAVEL, SEG_ARC, SEG_DOT, TWO_PI
    use base_text, only: text_t, str, mm
    use base_error, only: error_t
    implicit none
    private
    public :: gerber_image

    !> Coordinate units per tape unit: 6.6 format (1e-6 mm) / 0.01 mm.
    integer(int64), parameter :: PER_UNIT = 10000_int64

contains

    !> One image of the runs; labels: a comment per tape; tools: tool widths
    !> (units, > 0).
    subroutine gerber_image(runs, labels, tools, title, text)
        type(run_t), intent(in) :: runs(:)
        character(len=*), intent(in) :: labels(:)
        integer(int64), intent(in) :: tools(:)
        character(len=*), intent(in) :: title
        type(text_t), intent(inout) :: text
        integer :: l, mode
        logical :: known, got
        integer(int64) :: cx, cy, mx, my
        type(seg_t) :: s
        type(walker_t) :: w
        type(error_t), allocatable :: err
        call text%add('G04 ' // clean(title) // '*')
        call text%add('G04 millimetres from the start point, one aperture per tape*')
        call text%add('%FSLAX66Y66*%')
        call text%add('%MOMM*%')
        call text%add('%LPD*%')
        do l = 1, size(runs)
            call text%add('%ADD' // str(9 + l) // 'C,' // mm(tools(l)) // '00*%')
        end do
        call text%add('G75*')
        mode = 0
        known = .false.
        cx = 0
        cy = 0
        do l = 1, size(runs)
            call text%add('G04 ' // clean(trim(labels(l))) // ', tool ' // mm(tools(l)) // ' mm*')
            call text%add('D' // str(9 + l) // '*')
            call walk_start(w, runs(l), err)
            if (allocated(err)) exit
            do
                call next_seg(w, runs(l), s, got)
                if (.not. got) exit
                if (.not. known .or. cx /= s%x0 .or. cy /= s%y0) then
                    call text%add(xy(s%x0, s%y0) // 'D02*')
                    known = .true.
                end if
                select case (s%kind)
                case (SEG_TRAVEL)
                    call text%add(xy(s%x1, s%y1) // 'D02*')
                case (SEG_LINE)
                    call set_mode(1)
                    call text%add(xy(s%x1, s%y1) // 'D01*')
                case (SEG_DOT)
                    call text%add(xy(s%x0, s%y0) // 'D03*')
                case (SEG_ARC)
                    call set_mode(merge(2, 3, s%sweep < 0))
                    if (abs(s%sweep) >= TWO_PI - 1.0e-12_real64) then
                        mx = 2 * s%cx - s%x0
                        my = 2 * s%cy - s%y0
                        call text%add(xy(mx, my) // ij(s%cx - s%x0, s%cy - s%y0) // 'D01*')
                        call text%add(xy(s%x0, s%y0) // ij(s%cx - mx, s%cy - my) // 'D01*')
                    else
                        call text%add(xy(s%x1, s%y1) // ij(s%cx - s%x0, s%cy - s%y0) // 'D01*')
                    end if
                end select
                cx = s%x1
                cy = s%y1
            end do
        end do
        call text%add('M02*')
    contains
        subroutine set_mode(m)
            integer, intent(in) :: m
            if (m == mode) return
            mode = m
            call text%add('G0' // str(m) // '*')
        end subroutine set_mode
    end subroutine gerber_image

    function xy(x, y) result(s)
        integer(int64), intent(in) :: x, y
        character(len=:), allocatable :: s
        s = 'X' // str(x * PER_UNIT) // 'Y' // str(y * PER_UNIT)
    end function xy

    function ij(i, j) result(s)
        integer(int64), intent(in) :: i, j
        character(len=:), allocatable :: s
        s = 'I' // str(i * PER_UNIT) // 'J' // str(j * PER_UNIT)
    end function ij

    !> Comment text without the characters that end a Gerber word or command.
    function clean(s) result(t)
        character(len=*), intent(in) :: s
        character(len=len(s)) :: t
        integer :: i
        t = s
        do i = 1, len(t)
            if (t(i:i) == '*' .or. t(i:i) == '%' .or. iachar(t(i:i)) < 32 .or. &
                iachar(t(i:i)) > 126) t(i:i) = '_'
        end do
    end function clean

end module em703_gerber
