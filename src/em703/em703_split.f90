!> Splitting a long straight move into frames, as seed 004 (NC tape codes)
!> describes for a pulse multiplier whose counter holds N pulses: no frame moves
!> more than N-1 pulses on an axis, and every division point lies within one
!> pulse of the line. Frame k of n ends at the point k/n of the move rounded to
!> whole pulses, a half towards the start: the rule that gives the document's
!> table (98132, 87647 pulses in 10 frames of at most 9999) exactly. The same
!> rule is in the 1977 program (legacy/cmspl1.f) for the P card's FMAX, and in
!> the harness (seeds/seed004.py) as the oracle.
!>
!> split_equal is the document's other way: every frame equal but the last,
!> which takes up the error, the frame's tangent a convergent or
!> semiconvergent of the move's (continued fractions), chosen as
!> seeds/seed004.py chooses it (the same frames, tested).
module em703_split
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use base_error, only: no_memory
    implicit none
    private
    public :: frames_needed, split_move, split_frame, split_equal

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

    !> The move (dx, dy) as count equal frames (fx, fy) and a last frame
    !> (lx, ly) (none when it is (0, 0)), every frame at most max_pulses per
    !> axis, the sums exact. Along the longer axis u and the shorter v the
    !> frame is (m q, m p) for p/q a convergent or semiconvergent of v/u with
    !> q <= max_pulses and the largest m that lets the last frame fit (both
    !> of its components 0..max_pulses); of all candidates the one whose
    !> division points stray least from the line (k m |q v - p u| / L), then
    !> the fewest frames, then the smallest q. dev: that largest distance, in
    !> pulses. ok false when no candidate fits.
    subroutine split_equal(dx, dy, max_pulses, fx, fy, count, lx, ly, dev, ok)
        integer(int64), intent(in) :: dx, dy, max_pulses
        integer(int64), intent(out) :: fx, fy, count, lx, ly
        real(real64), intent(out) :: dev
        logical, intent(out) :: ok
        integer(int64) :: u, v, p0, q0, p1, q1, a, b, quot, t, tmp, p, q
        integer(int64) :: best(3), ba, bb, bk, bru, brv
        logical :: swap, found, stop_now
        fx = 0; fy = 0; count = 0; lx = 0; ly = 0; dev = 0
        ok = max_pulses >= 1
        if (.not. ok) return
        u = abs(dx); v = abs(dy)
        swap = v > u
        if (swap) then
            tmp = u; u = v; v = tmp
        end if
        if (u == 0) return
        found = .false.
        best = huge(1_int64)
        ba = 0; bb = 0; bk = 0; bru = 0; brv = 0
        stop_now = .false.
        call candidate(0_int64, 1_int64)
        p0 = 1; q0 = 0; p1 = 0; q1 = 1
        a = u; b = v
        do while (b /= 0 .and. .not. stop_now)
            quot = a / b
            do t = 1, quot
                p = p0 + t * p1
                q = q0 + t * q1
                call candidate(p, q)
                if (stop_now) exit
            end do
            tmp = p0 + quot * p1; p0 = p1; p1 = tmp
            tmp = q0 + quot * q1; q0 = q1; q1 = tmp
            tmp = a - quot * b; a = b; b = tmp
        end do
        ok = found
        if (.not. ok) return
        dev = real(best(1), real64) / hypot(real(u, real64), real(v, real64))
        count = bk
        call orient(ba, bb, fx, fy)
        call orient(bru, brv, lx, ly)

    contains

        !> Try the tangent p/q; stop_now once q passes the limit. The total
        !> multiplier c = k m must leave both remainders u - c q, v - c p in
        !> 0..max_pulses; the largest m with a k, then the largest k.
        subroutine candidate(p, q)
            integer(int64), intent(in) :: p, q
            integer(int64) :: m, k, ru, rv, err, key(3), clo, chi
            if (q > max_pulses) then
                stop_now = .true.
                return
            end if
            clo = max(1_int64, ceil_div(u - max_pulses, q))
            chi = u / q
            if (p > 0) then
                clo = max(clo, ceil_div(v - max_pulses, p))
                chi = min(chi, v / p)
            else if (v > max_pulses) then
                return
            end if
            if (clo > chi) return
            do m = max_pulses / q, 1, -1
                k = chi / m
                if (k * m < clo) cycle
                ru = u - k * m * q
                rv = v - k * m * p
                err = k * m * abs(q * v - p * u)
                key = [err, k + merge(1_int64, 0_int64, ru /= 0 .or. rv /= 0), q]
                if (.not. found .or. less(key, best)) then
                    found = .true.
                    best = key
                    ba = m * q; bb = m * p; bk = k; bru = ru; brv = rv
                end if
                exit
            end do
        end subroutine candidate

        !> ceiling(x / y) for y > 0.
        pure integer(int64) function ceil_div(x, y)
            integer(int64), intent(in) :: x, y
            ceil_div = x / y
            if (ceil_div * y < x) ceil_div = ceil_div + 1
        end function ceil_div

        logical function less(x, y)
            integer(int64), intent(in) :: x(3), y(3)
            integer :: i
            less = .false.
            do i = 1, 3
                if (x(i) /= y(i)) then
                    less = x(i) < y(i)
                    return
                end if
            end do
        end function less

        subroutine orient(x, y, ox, oy)
            integer(int64), intent(in) :: x, y
            integer(int64), intent(out) :: ox, oy
            if (swap) then
                ox = y; oy = x
            else
                ox = x; oy = y
            end if
            if (dx < 0) ox = -ox
            if (dy < 0) oy = -oy
        end subroutine orient

    end subroutine split_equal

end module em703_split
