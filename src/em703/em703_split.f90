!> Splitting a long straight move into frames, as seed 004 (NC tape codes)
!> describes for a pulse multiplier whose counter holds N pulses: no frame moves
!> more than N-1 pulses on an axis, and every division point lies within one
!> pulse of the line. Frame k of n ends at the point k/n of the move rounded to
!> whole pulses, a half towards the start: the rule that gives the document's
!> table (98132, 87647 pulses in 10 frames of at most 9999) exactly. The same
!> rule is in the 1977 program (legacy/cmspl1.f) for the P card's FMAX, and in
!> the harness (seeds/seed004.py) as the oracle.
module em703_split
    use, intrinsic :: iso_fortran_env, only: int64
    use base_error, only: no_memory
    implicit none
    private
    public :: frames_needed, split_move, split_frame

contains

    !> The fewest frames of at most max_pulses per axis for the move (dx, dy);
    !> 0 for no move at all.
    pure integer(int64) function frames_needed(dx, dy, max_pulses) result(n)
        integer(int64), intent(in) :: dx, dy, max_pulses
        n = (max(abs(dx), abs(dy)) + max_pulses - 1) / max_pulses
    end function frames_needed

    !> Point k/n of a move of d pulses, rounded to the nearest pulse with a
    !> half going towards the start (towards 0).
    pure integer(int64) function division_point(d, k, n) result(p)
        integer(int64), intent(in) :: d, k, n
        integer(int64) :: q, r
        q = (abs(d) * k) / n
        r = (abs(d) * k) - q * n
        if (2 * r > n) q = q + 1
        p = sign(q, d)
    end function division_point

    !> Frame k of the n frames of the move (dx, dy): (fx, fy).
    pure subroutine split_frame(dx, dy, k, n, fx, fy)
        integer(int64), intent(in) :: dx, dy, k, n
        integer(int64), intent(out) :: fx, fy
        fx = division_point(dx, k, n) - division_point(dx, k - 1, n)
        fy = division_point(dy, k, n) - division_point(dy, k - 1, n)
    end subroutine split_frame

    !> The frames (dxs(i), dys(i)), i = 1..n, of the move (dx, dy).
    subroutine split_move(dx, dy, max_pulses, dxs, dys)
        integer(int64), intent(in) :: dx, dy, max_pulses
        integer(int64), allocatable, intent(out) :: dxs(:), dys(:)
        integer(int64) :: n, k
        integer :: st
        n = frames_needed(dx, dy, max_pulses)
        allocate(dxs(n), dys(n), stat=st)
        if (st /= 0) call no_memory('the split move', 16 * n)
        do k = 1, n
            call split_frame(dx, dy, k, n, dxs(k), dys(k))
        end do
    end subroutine split_move

end module em703_split
