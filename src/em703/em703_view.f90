!> A picture of a punched tape for the terminal, one line per row: the row
!> number, the holes (`o`) with the feed hole (`.`), the row in octal and
!> what it means. For the 5-track EM-703 tape the feed hole lies between
!> tracks 3 and 2 (docs/TAPE.md); for 8-track ISO and EIA tape between
!> tracks 4 and 3.
module em703_view
    use em703_codec, only: DIGITS_8, DIGITS_K, ROW_GM, ROW_MINUS, ROW_X, ROW_Y, ROW_DX, &
                           ROW_DY, ROW_CYC, ROW_K, ROW_KK
    use em703_punch, only: iso_meaning, eia_meaning, iso_or_eia
    use base_text, only: text_t, str, octal
    implicit none
    private
    public :: view_tape, guess_code

    !> A tape image as rows (integers 0..255) or as bytes (a character a row).
    interface view_tape
        module procedure view_rows, view_bytes
    end interface view_tape
    interface guess_code
        module procedure guess_rows, guess_bytes
    end interface guess_code

contains

    function as_bytes(rows) result(data)
        integer, intent(in) :: rows(:)
        character(len=size(rows)) :: data
        integer :: i
        do i = 1, size(rows)
            data(i:i) = achar(iand(rows(i), 255))
        end do
    end function as_bytes

    function guess_rows(rows) result(code)
        integer, intent(in) :: rows(:)
        character(len=:), allocatable :: code
        code = guess_bytes(as_bytes(rows))
    end function guess_rows

    subroutine view_rows(rows, code, first, last, text)
        integer, intent(in) :: rows(:)
        character(len=*), intent(in) :: code
        integer, intent(in) :: first, last
        type(text_t), intent(inout) :: text
        call view_bytes(as_bytes(rows), code, first, last, text)
    end subroutine view_rows

    !> "em703" when every row fits 5 tracks; otherwise "iso" when most punched
    !> rows have an even number of holes, "eia" when most have an odd number
    !> (em703_punch's iso_or_eia).
    function guess_bytes(data) result(code)
        character(len=*), intent(in) :: data
        character(len=:), allocatable :: code
        if (all_five(data)) then
            code = 'em703'
            return
        end if
        code = iso_or_eia(data)
    end function guess_bytes

    logical function all_five(data)
        character(len=*), intent(in) :: data
        integer :: i
        all_five = .false.
        do i = 1, len(data)
            if (iachar(data(i:i)) > 31) return
        end do
        all_five = .true.
    end function all_five

    !> The picture of rows first..last of a tape in code "em703", "iso" or "eia".
    subroutine view_bytes(data, code, first, last, text)
        character(len=*), intent(in) :: data
        character(len=*), intent(in) :: code
        integer, intent(in) :: first, last
        type(text_t), intent(inout) :: text
        integer :: i, ntracks, feed_after, gm1, gm2, nz1, nz2
        logical :: controlled
        character(len=:), allocatable :: border
        if (code == 'em703') then
            ntracks = 5
            feed_after = 3             ! tracks 5 4 3 . 2 1
            call text%add('  row  5 4 3   2 1   code  meaning')
        else
            ntracks = 8
            feed_after = 4             ! tracks 8 7 6 5 4 . 3 2 1
            call text%add('  row  8 7 6 5 4   3 2 1   code  meaning')
        end if
        border = '      +' // repeat('-', 2 * ntracks + 5) // '+'
        call text%add(border)
        ! The first and the last punched row (leader before, trailer after).
        nz1 = len(data) + 1
        nz2 = 0
        do i = 1, len(data)
            if (row(i) /= 0) then
                nz1 = min(nz1, i)
                nz2 = i
            end if
        end do
        ! EM-703: the array bounds (first and last GM) and the code variant.
        gm1 = 0
        gm2 = 0
        controlled = .false.
        if (code == 'em703') then
            do i = 1, len(data)
                if (row(i) == ROW_GM) then
                    if (gm1 == 0) gm1 = i
                    gm2 = i
                end if
                if (gm1 == 0 .or. i <= gm1) cycle
                if (any(row(i) == DIGITS_K([3, 5, 6, 9]))) controlled = .true.
            end do
        end if
        do i = max(1, first), min(len(data), last)
            call text%add(picture(row(i), ntracks, feed_after, i) // '| ' // &
                          octal(row(i), 3) // '   ' // meaning(i))
        end do
        call text%add(border)
    contains
        integer function row(i)
            integer, intent(in) :: i
            row = iachar(data(i:i))
        end function row
        function meaning(i) result(s)
            integer, intent(in) :: i
            character(len=:), allocatable :: s
            select case (code)
            case ('iso')
                s = iso_meaning(row(i))
                if (row(i) == 0) s = blank_name(i)
            case ('eia')
                s = eia_meaning(row(i))
                if (row(i) == 0) s = blank_name(i)
            case default
                s = em703_meaning(row(i), controlled)
                if (row(i) == 0 .and. (gm1 == 0 .or. i < gm1)) s = 'leader'
                if (row(i) == 0 .and. gm2 > 0 .and. i > gm2) s = 'trailer'
            end select
        end function meaning
        !> A blank row of an 8-track tape: leader before the first punched
        !> row, trailer after the last one.
        function blank_name(i) result(s)
            integer, intent(in) :: i
            character(len=:), allocatable :: s
            s = 'blank'
            if (i < nz1) s = 'leader'
            if (i > nz2) s = 'trailer'
        end function blank_name
    end subroutine view_bytes

    !> "   21 |o o o . o o    " : the row number and the holes, tracks from the
    !> highest on the left, the feed hole after track feed_after.
    function picture(v, ntracks, feed_after, n) result(s)
        integer, intent(in) :: v, ntracks, feed_after, n
        character(len=:), allocatable :: s
        character(len=2 * ntracks + 5) :: inner
        integer :: t, p
        inner = ' '
        p = 1
        do t = ntracks, 1, -1
            if (btest(v, t - 1)) inner(p:p) = 'o'
            p = p + 2
            if (t == feed_after) then
                inner(p:p) = '.'
                p = p + 2
            end if
        end do
        s = repeat(' ', max(0, 5 - len(str(n)))) // str(n) // ' |' // inner
    end function picture

    !> What a row of an EM-703 tape means (Table I).
    function em703_meaning(v, controlled) result(s)
        integer, intent(in) :: v
        logical, intent(in) :: controlled
        character(len=:), allocatable :: s
        integer :: d
        select case (v)
        case (ROW_X); s = 'X'
        case (ROW_Y); s = 'Y'
        case (ROW_MINUS); s = '-'
        case (ROW_DX); s = 'DX'
        case (ROW_DY); s = 'DY'
        case (ROW_CYC); s = 'CYC'
        case (ROW_K); s = 'K'
        case (ROW_KK); s = 'KK'
        case (ROW_GM); s = 'GM'
        case default
            s = 'not an EM-703 code'
            do d = 0, 9
                if (controlled .and. v == DIGITS_K(d)) s = 'digit ' // str(d)
                if (.not. controlled .and. v == DIGITS_8(d)) s = 'digit ' // str(d)
            end do
            if (controlled .and. any(v == DIGITS_8([3, 5, 6, 9]))) &
                s = 'parity error (digit ' // str(v) // ' without track 5)'
            if (.not. controlled .and. any(v == DIGITS_K([3, 5, 6, 9]))) then
                do d = 0, 9
                    if (v == DIGITS_K(d)) s = 'digit ' // str(d) // ' of code K'
                end do
            end if
        end select
    end function em703_meaning

end module em703_view
