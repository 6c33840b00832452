!> The pads of a job's pad tapes as an Excellon drill file: for a 1977 board
!> every pad is a hole, and the small-pad tour is a drilling order.
!>
!> The pads are found again from what the tape draws (docs/TOOLS.md, "drill").
!> TENZOR fills a pad with passes around its centre: concentric circles for
!> a round pad, concentric rectangles for a rectangular one, a dot for a pad
!> as wide as the tool; a row of pads is drawn pass by pass along the row.
!> Each run of segments drawn with the tool down (between two raises) is a
!> pass; a pass that draws a circle or a dot belongs to the pad of its
!> centre (the centre of its box), so that overlapping holes stay apart;
!> passes of straight strokes only (the sides of rectangular pads in a row)
!> belong together when they overlap. Its size: a round pad's diameter is
!> the widest circle's plus the tool, a dot's the tool; a rectangular pad's
!> hole is its shorter side (the largest round hole it holds). The hits come
!> in the order the tape first reaches each pad: the small-pad tape's, then
!> the large-pad tape's; one tool per hole size, numbered by size.
!>
!> The file: M48, a comment, METRIC with decimal points, the tools (T01C0.500),
!> %, G90, G05, then the hits (X12.345Y-6.780 in mm from the start point,
!> three decimals: a centre lies on the 0.005 mm grid), a tool selected
!> whenever it changes, M30.
module em703_drill
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use em703_sim, only: run_t, seg_t, walker_t, walk_start, next_seg, seg_box, &
                         SEG_TRAVEL, SEG_ARC, SEG_DOT, SEG_RAISE
    use base_error, only: error_t, no_memory
    use base_text, only: text_t, str, fixed
    implicit none
    private
    public :: find_holes, drill_program

    !> A hole: its centre in half units (0.005 mm) and its diameter in units.
    type, public :: hole_t
        integer(int64) :: x2 = 0, y2 = 0
        integer(int64) :: d = 0
    end type hole_t

    !> A pass: what the tool draws between two raises, as the box of its
    !> tool-centre path (units); root: its pad (union-find); first: the
    !> first pass of its pad.
    type :: pass_t
        real(real64) :: box(4) = 0
        integer :: parent = 0
        logical :: centred = .false.     !< it draws a circle or a dot: its centre is its pad's
        integer(int64) :: x2 = 0, y2 = 0 !< its centre, half units
    end type pass_t

contains

    !> The holes of one tape (a run), in the order the tape first reaches
    !> each pad; tool: the tape's tool width, units. A pass that draws a
    !> circle or a dot belongs to the pad of its centre (the circles of a
    !> round pad are concentric), so that holes that overlap stay holes;
    !> passes of straight strokes only (the sides of a rectangular pad,
    !> drawn one by one along a row) belong together when their boxes,
    !> widened by half the tool, overlap (not merely touch).
    subroutine find_holes(run, tool, holes, n)
        type(run_t), intent(in) :: run
        integer(int64), intent(in) :: tool
        type(hole_t), allocatable, intent(inout) :: holes(:)   !< allocated; holes(1:n) in use
        integer, intent(inout) :: n
        type(pass_t), allocatable :: passes(:)
        integer, allocatable :: head(:), nxt(:), member(:)
        integer(int64), allocatable :: keys(:)
        integer :: npass, nentry, i, r, st
        real(real64) :: cell, box(4), b(4)
        type(walker_t) :: w
        type(error_t), allocatable :: err
        type(seg_t) :: s
        logical :: got, open, centred
        real(real64), allocatable :: pads(:, :)
        integer :: ncell
        cell = 4 * max(real(tool, real64), 25.0_real64)
        allocate(passes(64), head(0:255), keys(0:255), nxt(256), member(256))
        head = 0
        keys = 0
        npass = 0
        nentry = 0
        ncell = 0
        open = .false.
        call walk_start(w, run, err)
        if (allocated(err)) return
        do
            call next_seg(w, run, s, got)
            if (.not. got) exit
            if (s%kind == SEG_TRAVEL .or. s%kind == SEG_RAISE) then
                if (open) call close_pass()
                open = .false.
                cycle
            end if
            call seg_box(s, b)
            if (open) then
                box = [min(box(1), b(1)), max(box(2), b(2)), min(box(3), b(3)), max(box(4), b(4))]
            else
                box = b
                open = .true.
                centred = .false.
            end if
            if (s%kind == SEG_ARC .or. s%kind == SEG_DOT) centred = .true.
        end do
        if (open) call close_pass()
        ! each pad's box, kept at its first pass (a root is its pad's first)
        allocate(pads(4, npass), stat=st)
        if (st /= 0) call no_memory('the pads', int(npass, int64) * 32)
        do i = 1, npass
            r = root(i)
            if (r == i) then
                pads(:, i) = passes(i)%box
            else
                pads(:, r) = [min(pads(1, r), passes(i)%box(1)), max(pads(2, r), passes(i)%box(2)), &
                              min(pads(3, r), passes(i)%box(3)), max(pads(4, r), passes(i)%box(4))]
            end if
        end do
        do i = 1, npass
            if (passes(i)%parent == i) call add_hole(pads(:, i))
        end do
    contains
        !> A pass ends: it joins every pad it overlaps.
        subroutine close_pass()
            integer :: ix, iy, k, e, ix0, ix1, iy0, iy1
            real(real64) :: half
            half = real(tool, real64) / 2
            call grow_passes()
            npass = npass + 1
            passes(npass)%box = box
            passes(npass)%parent = npass
            passes(npass)%centred = centred
            passes(npass)%x2 = nint(box(1) + box(2), int64)
            passes(npass)%y2 = nint(box(3) + box(4), int64)
            if (centred) then
                ! its centre's cell: the passes of the same centre
                ix0 = floor(real(passes(npass)%x2, real64) / 2 / cell)
                ix1 = ix0
                iy0 = floor(real(passes(npass)%y2, real64) / 2 / cell)
                iy1 = iy0
            else
                ix0 = floor((box(1) - half) / cell)
                ix1 = floor((box(2) + half) / cell)
                iy0 = floor((box(3) - half) / cell)
                iy1 = floor((box(4) + half) / cell)
            end if
            do ix = ix0, ix1
                do iy = iy0, iy1
                    k = find_cell(ix, iy)
                    e = head(k)
                    do while (e > 0)
                        if (belong(passes(member(e)), passes(npass), half)) call join(member(e), npass)
                        e = nxt(e)
                    end do
                    call add_entry(k, npass)
                end do
            end do
        end subroutine close_pass

        !> Do passes a and c draw one pad?
        logical function belong(a, c, half)
            type(pass_t), intent(in) :: a, c
            real(real64), intent(in) :: half
            if (a%centred .neqv. c%centred) then
                belong = .false.
            else if (a%centred) then
                belong = a%x2 == c%x2 .and. a%y2 == c%y2
            else
                belong = overlap(a%box, c%box, half)
            end if
        end function belong

        logical function overlap(a, c, half)
            real(real64), intent(in) :: a(4), c(4), half
            overlap = a(1) - half < c(2) + half .and. c(1) - half < a(2) + half .and. &
                      a(3) - half < c(4) + half .and. c(3) - half < a(4) + half
        end function overlap

        !> Union by the smaller index: a pad's root is its first pass.
        subroutine join(a, c)
            integer, intent(in) :: a, c
            integer :: ra, rc
            ra = root(a)
            rc = root(c)
            if (ra == rc) return
            passes(max(ra, rc))%parent = min(ra, rc)
        end subroutine join

        integer function root(a) result(r)
            integer, intent(in) :: a
            r = a
            do while (passes(r)%parent /= r)
                passes(r)%parent = passes(passes(r)%parent)%parent
                r = passes(r)%parent
            end do
        end function root

        !> The slot of cell (ix, iy) in the cell table (open addressing; made
        !> bigger when half full).
        integer function find_cell(ix, iy) result(k)
            integer, intent(in) :: ix, iy
            integer(int64) :: key
            key = int(ix, int64) * 4294967296_int64 + int(iy, int64) + 2147483648_int64
            k = probe(key)
            if (head(k) == 0) then
                if (2 * (ncell + 1) > size(head)) then
                    call rehash()
                    k = probe(key)
                end if
                keys(k) = key
                head(k) = -1
                ncell = ncell + 1
            end if
        end function find_cell

        integer function probe(key) result(k)
            integer(int64), intent(in) :: key
            integer(int64) :: v
            ! bits mixed by shifts and exclusive ors only: no product that
            ! could overflow (the run-time checks trap a signed overflow)
            v = ieor(key, ishft(key, -33))
            v = ieor(v, ishft(v, 21))
            v = ieor(v, ishft(v, -17))
            v = ieor(v, ishft(v, 7))
            k = int(iand(v, int(size(head) - 1, int64)))
            do while (head(k) /= 0 .and. keys(k) /= key)
                k = iand(k + 1, size(head) - 1)
            end do
        end function probe

        subroutine rehash()
            integer, allocatable :: oldhead(:)
            integer(int64), allocatable :: oldkeys(:)
            integer :: j, k, st
            call move_alloc(head, oldhead)
            call move_alloc(keys, oldkeys)
            allocate(head(0:4 * size(oldhead) - 1), keys(0:4 * size(oldhead) - 1), stat=st)
            if (st /= 0) call no_memory('the cells of the pads', int(48 * size(oldhead), int64))
            head = 0
            keys = 0
            do j = 0, size(oldhead) - 1
                if (oldhead(j) == 0) cycle
                k = probe(oldkeys(j))
                head(k) = oldhead(j)
                keys(k) = oldkeys(j)
            end do
        end subroutine rehash

        subroutine add_entry(k, p)
            integer, intent(in) :: k, p
            integer, allocatable :: more(:)
            integer :: st
            if (nentry == size(nxt)) then
                allocate(more(2 * size(nxt)), stat=st)
                if (st /= 0) call no_memory('the cells of the pads', int(8 * size(nxt), int64))
                more(1:nentry) = nxt(1:nentry)
                call move_alloc(more, nxt)
                allocate(more(2 * size(member)), stat=st)
                if (st /= 0) call no_memory('the cells of the pads', int(8 * size(member), int64))
                more(1:nentry) = member(1:nentry)
                call move_alloc(more, member)
            end if
            nentry = nentry + 1
            member(nentry) = p
            nxt(nentry) = max(head(k), 0)
            head(k) = nentry
        end subroutine add_entry

        subroutine grow_passes()
            type(pass_t), allocatable :: more(:)
            integer :: st
            if (npass < size(passes)) return
            allocate(more(2 * size(passes)), stat=st)
            if (st /= 0) call no_memory('the passes of the tape', int(2 * size(passes), int64) * 40)
            more(1:npass) = passes(1:npass)
            call move_alloc(more, passes)
        end subroutine grow_passes

        !> A pad: its centre, and its hole: the shorter side of its box plus
        !> the tool (a round pad's diameter; a dot's is the tool's).
        subroutine add_hole(box)
            real(real64), intent(in) :: box(4)
            type(hole_t), allocatable :: more(:)
            type(hole_t) :: h
            integer :: st
            h%x2 = nint(box(1) + box(2), int64)
            h%y2 = nint(box(3) + box(4), int64)
            h%d = nint(min(box(2) - box(1), box(4) - box(3)), int64) + tool
            if (n == size(holes)) then
                allocate(more(max(64, 2 * size(holes))), stat=st)
                if (st /= 0) call no_memory('the holes', int(2 * size(holes), int64) * 24)
                more(1:n) = holes(1:n)
                call move_alloc(more, holes)
            end if
            n = n + 1
            holes(n) = h
        end subroutine add_hole
    end subroutine find_holes

    !> The drill file of the holes, in their order.
    subroutine drill_program(holes, title, text)
        type(hole_t), intent(in) :: holes(:)
        character(len=*), intent(in) :: title
        type(text_t), intent(inout) :: text
        integer(int64), allocatable :: sizes(:)
        integer :: i, j, nsize, current, t, st
        ! the hole sizes, ascending
        allocate(sizes(size(holes)), stat=st)
        if (st /= 0) call no_memory('the hole sizes', int(size(holes), int64) * 8)
        nsize = 0
        do i = 1, size(holes)
            if (any(sizes(1:nsize) == holes(i)%d)) cycle
            j = nsize
            do while (j > 0)
                if (sizes(j) < holes(i)%d) exit
                sizes(j + 1) = sizes(j)
                j = j - 1
            end do
            sizes(j + 1) = holes(i)%d
            nsize = nsize + 1
        end do
        call text%add('M48')
        call text%add('; ' // clean(title))
        call text%add('; one hit per pad, in the order the tapes reach them; mm from the start point')
        call text%add('METRIC,TZ')
        do i = 1, nsize
            call text%add('T' // two(i) // 'C' // fixed(real(sizes(i), real64) / 100, 3))
        end do
        call text%add('%')
        call text%add('G90')
        call text%add('G05')
        current = 0
        do i = 1, size(holes)
            t = findloc(sizes(1:nsize), holes(i)%d, dim=1)
            if (t /= current) then
                call text%add('T' // two(t))
                current = t
            end if
            call text%add('X' // halves_mm(holes(i)%x2) // 'Y' // halves_mm(holes(i)%y2))
        end do
        call text%add('M30')
    contains
        function two(k) result(s)
            integer, intent(in) :: k
            character(len=:), allocatable :: s
            s = str(k)
            if (k < 10) s = '0' // s
        end function two
    end subroutine drill_program

    !> Half units (0.005 mm) as mm with three decimals.
    function halves_mm(v) result(s)
        integer(int64), intent(in) :: v
        character(len=:), allocatable :: s
        integer(int64) :: a
        character(len=3) :: frac
        a = abs(v) * 5                      ! thousandths of a mm
        write(frac, '(i3.3)') mod(a, 1000_int64)
        s = str(a / 1000) // '.' // frac
        if (v < 0) s = '-' // s
    end function halves_mm

    !> Comment text in printable ASCII.
    function clean(s) result(t)
        character(len=*), intent(in) :: s
        character(len=len(s)) :: t
        integer :: i
        t = s
        do i = 1, len(t)
            if (iachar(t(i:i)) < 32 .or. iachar(t(i:i)) > 126) t(i:i) = '_'
        end do
    end function clean

end module em703_drill
