!> Text helpers of the em703 tools: a growing text buffer, and numbers
!> formatted the same way on every machine (integers, fixed decimals without
!> a negative zero, octal).
module base_text
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use base_error, only: no_memory
    use base_files, only: write_out
    implicit none
    private
    public :: text_t, str, fixed, mm, octal, lower, starts_with, ends_with, parse_int, parse_mm, &
              parse_real

    !> Lines of text kept in one string, each ending in a newline. A text
    !> attached to a file descriptor (attach) is a stream: what it holds is
    !> written out whenever it passes DRAIN_AT bytes and by drain, so a text
    !> of any length takes a bounded buffer. The first failed write is kept
    !> (message) and later writes are skipped.
    type :: text_t
        character(len=:), allocatable :: s     !< the text; only s(1:n) is valid
        integer :: n = 0                       !< length in use
        integer :: fd = -1                     !< the stream's descriptor, -1: none
        integer(int64) :: written = 0          !< bytes written out so far
        character(len=:), allocatable :: message  !< why a write failed
    contains
        procedure :: add => text_add
        procedure :: put => text_put
        procedure :: value => text_value
        procedure :: attach => text_attach
        procedure :: drain => text_drain
    end type text_t

    !> A stream's buffer is written out past this many bytes.
    integer, parameter :: DRAIN_AT = 1048576

    interface str
        module procedure str_int, str_int64
    end interface str

contains

    !> Append a line (the newline is added).
    subroutine text_add(self, line)
        class(text_t), intent(inout) :: self
        character(len=*), intent(in) :: line
        call self%put(line // achar(10))
    end subroutine text_add

    !> Append characters as they are.
    subroutine text_put(self, chars)
        class(text_t), intent(inout) :: self
        character(len=*), intent(in) :: chars
        character(len=:), allocatable :: bigger
        integer :: need, st
        if (self%fd >= 0 .and. self%n > 0 .and. self%n + len(chars) > DRAIN_AT) call self%drain()
        need = self%n + len(chars)
        if (.not. allocated(self%s)) then
            allocate(character(len=max(4096, need)) :: self%s, stat=st)
            if (st /= 0) call no_memory('the text', int(need, int64))
        end if
        if (need > len(self%s)) then
            allocate(character(len=max(need, 2 * len(self%s))) :: bigger, stat=st)
            if (st /= 0) call no_memory('the text', 2 * int(len(self%s), int64))
            bigger(1:self%n) = self%s(1:self%n)
            call move_alloc(bigger, self%s)
        end if
        self%s(self%n + 1:need) = chars
        self%n = need
    end subroutine text_put

    !> Make the text a stream into file descriptor fd (1 = standard output,
    !> or a file of base_files' open_out).
    subroutine text_attach(self, fd)
        class(text_t), intent(inout) :: self
        integer, intent(in) :: fd
        self%fd = fd
        self%written = 0
    end subroutine text_attach

    !> Write out what a stream holds.
    subroutine text_drain(self)
        class(text_t), intent(inout) :: self
        character(len=:), allocatable :: msg
        if (self%fd < 0 .or. self%n == 0) return
        if (.not. allocated(self%message)) then
            call write_out(self%fd, self%s(1:self%n), msg)
            if (len(msg) > 0) then
                self%message = msg
            else
                self%written = self%written + self%n
            end if
        end if
        self%n = 0
    end subroutine text_drain

    !> The text so far.
    function text_value(self) result(s)
        class(text_t), intent(in) :: self
        character(len=:), allocatable :: s
        if (allocated(self%s)) then
            s = self%s(1:self%n)
        else
            s = ''
        end if
    end function text_value

    !> An integer in decimal, no blanks.
    function str_int(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        s = str_int64(int(i, int64))
    end function str_int

    !> (by hand: the translators write millions of numbers, and an internal
    !> WRITE costs a microsecond each)
    function str_int64(i) result(s)
        integer(int64), intent(in) :: i
        character(len=:), allocatable :: s
        character(len=24) :: buf
        integer(int64) :: v
        integer :: p
        if (i == -huge(i) - 1) then
            write(buf, '(i0)') i
            s = trim(buf)
            return
        end if
        v = abs(i)
        p = len(buf) + 1
        do
            p = p - 1
            buf(p:p) = achar(iachar('0') + int(mod(v, 10_int64)))
            v = v / 10
            if (v == 0) exit
        end do
        if (i < 0) then
            p = p - 1
            buf(p:p) = '-'
        end if
        s = buf(p:)
    end function str_int64

    !> value rounded to `decimals` places (half away from zero), e.g. fixed(2.5d0, 2)
    !> = "2.50"; never "-0.00"; decimals 0..9.
    function fixed(value, decimals) result(s)
        real(real64), intent(in) :: value
        integer, intent(in) :: decimals
        character(len=:), allocatable :: s
        integer(int64) :: scaled, p
        character(len=:), allocatable :: digits
        logical :: negative
        p = 10_int64 ** decimals
        scaled = nint(abs(value) * real(p, real64), int64)
        negative = value < 0 .and. scaled /= 0
        digits = str(scaled / p)
        if (decimals > 0) then
            s = str(mod(scaled, p) + p)           ! leading 1 keeps the zeros
            digits = digits // '.' // s(2:)
        end if
        if (negative) digits = '-' // digits
        s = digits
    end function fixed

    !> A length in tape units (0.01 mm) as millimetres with two decimals, exact.
    function mm(units) result(s)
        integer(int64), intent(in) :: units
        character(len=:), allocatable :: s
        character(len=:), allocatable :: frac
        frac = str(mod(abs(units), 100_int64) + 100)
        s = str(abs(units) / 100) // '.' // frac(2:3)
        if (units < 0) s = '-' // s
    end function mm

    !> i in octal with at least `width` digits (zeros in front).
    function octal(i, width) result(s)
        integer, intent(in) :: i, width
        character(len=:), allocatable :: s
        character(len=24) :: buf
        write(buf, '(o0)') i
        s = trim(buf)
        if (len(s) < width) s = repeat('0', width - len(s)) // s
    end function octal

    !> ASCII lower case.
    function lower(s) result(t)
        character(len=*), intent(in) :: s
        character(len=len(s)) :: t
        integer :: i, c
        t = s
        do i = 1, len(s)
            c = iachar(s(i:i))
            if (c >= iachar('A') .and. c <= iachar('Z')) t(i:i) = achar(c + 32)
        end do
    end function lower

    logical function starts_with(s, prefix)
        character(len=*), intent(in) :: s, prefix
        starts_with = .false.
        if (len(s) >= len(prefix)) starts_with = s(1:len(prefix)) == prefix
    end function starts_with

    logical function ends_with(s, suffix)
        character(len=*), intent(in) :: s, suffix
        ends_with = .false.
        if (len(s) >= len(suffix)) ends_with = s(len(s) - len(suffix) + 1:) == suffix
    end function ends_with

    !> A decimal integer: optional sign, digits only (at most 18).
    subroutine parse_int(s, value, ok)
        character(len=*), intent(in) :: s
        integer(int64), intent(out) :: value
        logical, intent(out) :: ok
        integer :: i, i0
        value = 0
        ok = .false.
        i0 = 1
        if (len(s) > 0) then
            if (s(1:1) == '-' .or. s(1:1) == '+') i0 = 2
        end if
        if (len(s) < i0 .or. len(s) - i0 + 1 > 18) return
        do i = i0, len(s)
            if (s(i:i) < '0' .or. s(i:i) > '9') return
            value = value * 10 + (iachar(s(i:i)) - iachar('0'))
        end do
        if (s(1:1) == '-') value = -value
        ok = .true.
    end subroutine parse_int

    !> Millimetres with at most two decimals ("12.5", "-0.05", "100") as exact
    !> tape units (0.01 mm).
    subroutine parse_mm(s, units, ok)
        character(len=*), intent(in) :: s
        integer(int64), intent(out) :: units
        logical, intent(out) :: ok
        integer :: p, nd
        integer(int64) :: whole, frac
        character(len=:), allocatable :: a, b
        logical :: negative
        units = 0
        ok = .false.
        p = index(s, '.')
        if (p == 0) then
            a = s
            b = ''
        else
            a = s(1:p - 1)
            b = s(p + 1:)
        end if
        nd = len(b)
        if (nd > 2 .or. (len(a) == 0 .and. nd == 0)) return
        negative = .false.
        if (len(a) > 0) then
            negative = a(1:1) == '-'
            if (a == '-' .or. a == '+') then
                a = '0'
            end if
            call parse_int(a, whole, ok)
            if (.not. ok) return
            ! units must fit an int64: a longer number would wrap (2**64 + 84
            ! units read as 0.84 mm), and is beyond every range anyway
            if (abs(whole) > (huge(whole) - 99) / 100) then
                ok = .false.
                return
            end if
        else
            whole = 0
        end if
        frac = 0
        if (nd > 0) then
            if (b(1:1) == '-' .or. b(1:1) == '+') then
                ok = .false.
                return
            end if
            call parse_int(b, frac, ok)
            if (.not. ok) return
            if (nd == 1) frac = frac * 10
        end if
        units = abs(whole) * 100 + frac
        if (negative) units = -units
        ok = .true.
    end subroutine parse_mm

    !> A decimal number ("0.005", "-2", "1e-3" is refused): sign, digits, one point.
    subroutine parse_real(s, value, ok)
        character(len=*), intent(in) :: s
        real(real64), intent(out) :: value
        logical, intent(out) :: ok
        integer :: i, ndigits, npoints, ios
        value = 0
        ok = .false.
        ndigits = 0
        npoints = 0
        do i = 1, len(s)
            select case (s(i:i))
            case ('0':'9')
                ndigits = ndigits + 1
            case ('.')
                npoints = npoints + 1
            case ('-', '+')
                if (i /= 1) return
            case default
                return
            end select
        end do
        if (ndigits == 0 .or. npoints > 1 .or. len(s) > 40) return
        read(s, *, iostat=ios) value
        ok = ios == 0
    end subroutine parse_real

end module base_text
