!> Text (such as a G-code program) punched on 8-track tape in the two NC codes
!> of seed 004 ("Кодирование технологических команд"): ISO 7-bit and EIA
!> RS-244.
!>
!> ISO 7-bit: the character's ASCII code on tracks 1-7, track 8 added so that
!> every row has an even number of holes; a line ends with LF (end of block).
!> EIA RS-244: digits in 8-4-2-1 on tracks 4-3-2-1 (0 is track 6 alone); the
!> letters a-i are 1-9 with tracks 6 and 7, j-r are 1-9 with track 7, s-z are
!> 2-9 with track 6; track 5 is added so that every row has an odd number of
!> holes; track 8 alone is the end of block. Upper-case letters are punched as
!> the letters (EIA has one case). The few symbols, from RS-244 as the NC
!> manuals print it: space 5, minus 7, plus 5-6-7, period 1-2-4-6-7, comma
!> 1-2-4-5-6, slash 1-5-6, tab 2-3-4-5-6, parentheses (control out / in)
!> 2-4-5 and 2-4-7. `%` (rewind stop) is 1-2-4 here, a reconstruction: the
!> seed gives no holes for it (docs/TOOLS.md).
!>
!> A tape image has one byte per row (track k = bit k-1), a leader and a
!> trailer of LEADER blank rows (feed holes only). A carriage return is
!> dropped (CR LF is one end of block); another character outside the code is
!> an error naming its line and column.
module em703_punch
    use, intrinsic :: iso_fortran_env, only: int64
    use base_error, only: error_t, new_error, AT_LINE, no_memory
    use base_text, only: octal
    implicit none
    private
    public :: punch_text, iso_row, eia_row, iso_meaning, eia_meaning, holes, eia_char, iso_or_eia

    integer, parameter, public :: LEADER = 20
    integer, parameter, public :: EIA_EOB = 128
    !> The delete rows, how a punch operator rubs out a row (every hole of
    !> the code punched over it): ISO DEL with its parity track, all eight
    !> tracks; EIA tracks 1-7. A reader skips them.
    integer, parameter, public :: ISO_DELETE = 255, EIA_DELETE = 127
    integer, parameter :: TRACK5 = 16, TRACK8 = 128

contains

    !> Number of holes in a row.
    integer function holes(v)
        integer, intent(in) :: v
        holes = popcnt(iand(v, 255))
    end function holes

    !> The ISO row of an ASCII code 0..127 (track 8 makes the parity even).
    integer function iso_row(c)
        integer, intent(in) :: c
        iso_row = c
        if (mod(holes(c), 2) == 1) iso_row = c + TRACK8
    end function iso_row

    !> The EIA row of a character (its ASCII code), or -1 if EIA has none.
    !> Newline gives the end of block.
    integer function eia_row(c)
        integer, intent(in) :: c
        integer :: base
        base = -1
        select case (c)
        case (iachar('0'))
            base = 32                                   ! track 6
        case (iachar('1'):iachar('9'))
            base = c - iachar('0')
        case (iachar('a'):iachar('i'))
            base = 96 + c - iachar('a') + 1             ! tracks 6, 7
        case (iachar('A'):iachar('I'))
            base = 96 + c - iachar('A') + 1
        case (iachar('j'):iachar('r'))
            base = 64 + c - iachar('j') + 1             ! track 7
        case (iachar('J'):iachar('R'))
            base = 64 + c - iachar('J') + 1
        case (iachar('s'):iachar('z'))
            base = 32 + c - iachar('s') + 2             ! track 6
        case (iachar('S'):iachar('Z'))
            base = 32 + c - iachar('S') + 2
        case (32)
            base = 0                                    ! space: track 5 alone
        case (iachar('-'))
            base = 64                                   ! track 7
        case (iachar('+'))
            base = 96                                   ! 5, 6, 7
        case (iachar('.'))
            base = 1 + 2 + 8 + 32 + 64                  ! 1, 2, 4, 6, 7
        case (iachar(','))
            base = 1 + 2 + 8 + 32                       ! 1, 2, 4, (5), 6
        case (iachar('/'))
            base = 1 + 32                               ! 1, (5), 6
        case (9)
            base = 2 + 4 + 8 + 32                       ! tab: 2, 3, 4, (5), 6
        case (iachar('('))
            base = 2 + 8                                ! control out: 2, 4, (5)
        case (iachar(')'))
            base = 2 + 8 + 64                           ! control in: 2, 4, 7
        case (iachar('%'))
            base = 1 + 2 + 8                            ! rewind stop: 1, 2, 4
        case (10)
            eia_row = EIA_EOB
            return
        end select
        eia_row = base
        if (base < 0) return
        if (mod(holes(base), 2) == 0) eia_row = base + TRACK5
    end function eia_row

    !> The character of an EIA row read back (its ASCII code; the letters
    !> upper case, LF for the end of block), or -1 for a row that is no EIA
    !> code (a parity error among them).
    integer function eia_char(v) result(c)
        integer, intent(in) :: v
        if (v == EIA_EOB) then
            c = 10
            return
        end if
        do c = 9, 122
            if (c >= iachar('a') .and. c <= iachar('z')) cycle     ! the letters once
            if (eia_row(c) == v) return
        end do
        c = -1
    end function eia_char

    !> The code of an 8-track tape image (one byte a row): "iso" when at
    !> least as many of its punched rows have an even number of holes as an
    !> odd number, else "eia". Blank rows do not count.
    function iso_or_eia(data) result(code)
        character(len=*), intent(in) :: data
        character(len=:), allocatable :: code
        integer :: i, even, odd, v
        even = 0
        odd = 0
        do i = 1, len(data)
            v = iachar(data(i:i))
            if (v == 0) cycle
            if (mod(holes(v), 2) == 0) then
                even = even + 1
            else
                odd = odd + 1
            end if
        end do
        code = merge('iso', 'eia', even >= odd)
    end function iso_or_eia

    !> Punch text as a tape image in code "iso" or "eia".
    subroutine punch_text(text, code, rows, err)
        character(len=*), intent(in) :: text
        character(len=*), intent(in) :: code
        integer, allocatable, intent(out) :: rows(:)
        type(error_t), allocatable, intent(out) :: err
        integer, allocatable :: buf(:)
        integer :: i, n, c, r, line, col, st
        allocate(buf(len(text) + 2 * LEADER), stat=st)
        if (st /= 0) call no_memory('the tape image', 4 * (int(len(text), int64) + 2 * LEADER))
        buf = 0
        if (code /= 'iso' .and. code /= 'eia') then
            call new_error(err, 'code must be iso or eia, not "' // code // '"')
            return
        end if
        n = LEADER
        line = 1
        col = 0
        do i = 1, len(text)
            c = iachar(text(i:i))
            col = col + 1
            if (c == 13) cycle
            if (c > 127 .or. (c < 32 .and. c /= 10 .and. c /= 9) .or. c == 127) then
                call new_error(err, 'byte ' // octal(c, 3) // ' (octal) is not a character of ' // &
                    'the ' // upper(code) // ' code (' // trim(merge( &
                    'ASCII letters, digits, signs, tab, newline                 ', &
                    'letters, digits, space - + . , / ( ) %, tab, newline       ', code == 'iso')) // &
                    ')', AT_LINE, line, col)
                return
            end if
            if (code == 'iso') then
                r = iso_row(c)
            else
                r = eia_row(c)
                if (r < 0) then
                    call new_error(err, '"' // achar(c) // '" has no EIA RS-244 code', &
                                   AT_LINE, line, col)
                    return
                end if
            end if
            n = n + 1
            buf(n) = r
            if (c == 10) then
                line = line + 1
                col = 0
            end if
        end do
        rows = buf(1:n + LEADER)
    end subroutine punch_text

    function upper(s) result(t)
        character(len=*), intent(in) :: s
        character(len=len(s)) :: t
        integer :: i
        t = s
        do i = 1, len(s)
            if (s(i:i) >= 'a' .and. s(i:i) <= 'z') t(i:i) = achar(iachar(s(i:i)) - 32)
        end do
    end function upper

    !> What an ISO row means: the character, or a parity error.
    function iso_meaning(v) result(s)
        integer, intent(in) :: v
        character(len=:), allocatable :: s
        integer :: c
        c = iand(v, 127)
        if (mod(holes(v), 2) == 1) then
            s = 'parity error (odd number of holes)'
            return
        end if
        select case (c)
        case (0); s = 'blank'
        case (9); s = 'tab'
        case (10); s = 'end of block (LF)'
        case (13); s = 'carriage return'
        case (32); s = 'space'
        case (127); s = 'delete'
        case (33:126); s = achar(c)
        case default; s = 'control ' // octal(c, 3)
        end select
    end function iso_meaning

    !> What an EIA row means: the character, the end of block, or an error.
    function eia_meaning(v) result(s)
        integer, intent(in) :: v
        character(len=:), allocatable :: s
        integer :: c
        if (v == 0) then
            s = 'blank'
            return
        end if
        if (v == EIA_EOB) then
            s = 'end of block'
            return
        end if
        if (iand(v, TRACK8) /= 0) then
            s = 'track 8 with other holes (not an EIA code)'
            return
        end if
        if (mod(holes(v), 2) == 0) then
            s = 'parity error (even number of holes)'
            return
        end if
        if (v == EIA_DELETE) then
            s = 'delete'
            return
        end if
        c = eia_char(v)
        select case (c)
        case (-1); s = 'not an EIA code'
        case (9); s = 'tab'
        case (32); s = 'space'
        case (iachar('%')); s = '% (rewind stop)'
        case (iachar('(')); s = '( (control out)'
        case (iachar(')')); s = ') (control in)'
        case default; s = achar(c)
        end select
    end function eia_meaning

end module em703_punch
