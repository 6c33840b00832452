!> The EM-703 tape code: decode and check a tape image, encode frames, and
!> write frames as text.
!>
!> Source: Pakhomov, JINR P11-10356 (1977), Table I "Коды координатографа
!> ЭМ-703" and "Состав кадра"; docs/TAPE.md and docs/FILES.md. The table is
!> transcribed here from the report, independently of legacy/tzcode.f and of
!> harness/tape.py.
!>
!> A tape image holds one byte per row, the row in the low 5 bits; rows are
!> numbered from 1 = the first byte. Layout: blank leader, GM, frames, GM, blank
!> trailer. The decoder reads like the machine's reader, row by row, and stops
!> at the first error: its row, what was found and what was expected. An error
!> found only when the data ends names the row just past the last one.
module em703_codec
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use base_error, only: error_t, new_error, AT_ROW, no_memory
    use base_text, only: str, octal, fixed, text_t
    implicit none
    private
    public :: frame_t, tape_t, decode_tape, decoder_start, next_frame, &
              encode_tape, frame_rows, frame_text, &
              tape_text, on_circle, frame_problem, describe_row

    ! Table I: service codes (octal), the same in both variants.
    integer, parameter, public :: ROW_BLANK = 0
    integer, parameter, public :: ROW_X = int(o'12'), ROW_Y = int(o'13'), ROW_MINUS = int(o'14')
    integer, parameter, public :: ROW_K = int(o'16'), ROW_KK = int(o'17')
    integer, parameter, public :: ROW_DX = int(o'20'), ROW_DY = int(o'21')
    integer, parameter, public :: ROW_CYC = int(o'30'), ROW_GM = int(o'37')
    !> Digits 0..9 in the "8" code (the digit in binary) and in the "8 code with
    !> control" (3, 5, 6, 9 get track 5: octal 23, 25, 26, 31).
    integer, parameter, public :: DIGITS_8(0:9) = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]
    integer, parameter, public :: DIGITS_K(0:9) = [0, 1, 2, int(o'23'), 4, int(o'25'), &
                                                   int(o'26'), 7, 8, int(o'31')]
    !> Largest arc radius: 10 m in 0.01 mm units; an arc end may be off its
    !> circle by at most ARC_TOLERANCE units.
    integer(int64), parameter, public :: MAX_RADIUS = 1000000_int64
    integer(int64), parameter, public :: ARC_TOLERANCE = 1_int64
    !> Largest number on a tape (nine digits): a reconstruction limit, far
    !> beyond the field at any machine scale (1200 mm at 1:100 is 12000000).
    integer(int64), parameter, public :: MAX_NUMBER = 999999999_int64

    ! Kinds of rows, and the frame fields in their fixed order.
    integer, parameter :: KIND_DIGIT = 0, KIND_X = 1, KIND_Y = 2, KIND_DX = 3, &
                          KIND_DY = 4, KIND_CYC = 5, KIND_K = 6, KIND_KK = 7, &
                          KIND_MINUS = 8, KIND_GM = 9
    character(len=3), parameter :: FIELD_NAME(5) = ['X  ', 'Y  ', 'DX ', 'DY ', 'CYC']

    !> One frame; 0 = the field is absent (a zero is never punched). cyc is the
    !> number of executions of this frame and the next (0 = no cycle); k is
    !> 10, 20, 11 or 13. row is the row of the frame's first code, rows(1:6)
    !> the rows of X, Y, DX, DY, CYC, K (0 = absent).
    type, public :: frame_t
        integer(int64) :: x = 0, y = 0, dx = 0, dy = 0
        integer(int64) :: cyc = 0
        integer :: k = 10
        integer :: row = 0
        integer :: rows(6) = 0
    end type frame_t

    !> A decoded tape: its code variant ("8" or "K"), whether the variant was
    !> told by a row (false: no digit row tells 8 from K), whether the opening
    !> GM was found, the frames, the length in rows.
    type, public :: tape_t
        character(len=1) :: code = '8'
        logical :: told = .false.
        logical :: opened = .false.     !< the opening GM was read
        integer :: nrows = 0
        integer :: nframes = 0
        type(frame_t), allocatable :: frames(:)
    end type tape_t

    type :: row_t
        integer :: n = 0          !< row number
        integer :: value = 0      !< 0..31
        integer :: kind = 0       !< KIND_*
        integer :: digit = -1     !< the digit of a digit row
    end type row_t

    !> The reader's state; the tape image (a byte a row) is passed to every
    !> call, so that it is held once, by whoever read it.
    type :: reader_t
        integer :: n = 0              !< rows in the image
        integer :: i = 0              !< rows consumed
        character(len=1) :: code = '8'
        integer :: evidence = 0       !< auto mode: the row that told the code
        integer :: digit_of(0:31) = -1
        integer :: foreign(0:31) = -1 !< digit of a row of the other variant
    end type reader_t

    !> A tape read frame by frame (decoder_start, next_frame): the code
    !> variant, whether a row told it, whether the opening GM was found, the
    !> rows of the image and the frames read so far.
    type, public :: decoder_t
        character(len=1) :: code = '8'
        logical :: told = .false.
        integer :: evidence = 0          !< the row whose digit told the variant (auto), or 0
        logical :: opened = .false.
        integer :: nrows = 0
        integer :: nframes = 0
        logical :: done = .true.         !< no frame left (end, or an error)
        integer :: opener_row = 0        !< CYC row of an open cycle pair
        type(reader_t) :: rd
    end type decoder_t

contains

    ! ------------------------------------------------------------------
    ! Describing rows in messages.
    ! ------------------------------------------------------------------

    !> A row for a message whatever the code: "X (12)", "digit 3 (23)", "row 33".
    function describe_row(value) result(s)
        integer, intent(in) :: value
        character(len=:), allocatable :: s
        integer :: d
        s = service_name(value)
        if (len(s) > 0) then
            s = s // ' (' // octal(value, 2) // ')'
            return
        end if
        do d = 0, 9
            if (DIGITS_8(d) == value .or. DIGITS_K(d) == value) then
                s = 'digit ' // str(d) // ' (' // octal(value, 2) // ')'
                return
            end if
        end do
        s = 'row ' // octal(value, 2)
    end function describe_row

    !> Name of a service code, "" for others.
    function service_name(value) result(s)
        integer, intent(in) :: value
        character(len=:), allocatable :: s
        select case (value)
        case (ROW_MINUS); s = 'minus'
        case (ROW_X); s = 'X'
        case (ROW_Y); s = 'Y'
        case (ROW_DX); s = 'DX'
        case (ROW_DY); s = 'DY'
        case (ROW_CYC); s = 'CYC'
        case (ROW_K); s = 'K'
        case (ROW_KK); s = 'KK'
        case (ROW_GM); s = 'GM'
        case default; s = ''
        end select
    end function service_name

    integer function service_kind(value)
        integer, intent(in) :: value
        select case (value)
        case (ROW_MINUS); service_kind = KIND_MINUS
        case (ROW_X); service_kind = KIND_X
        case (ROW_Y); service_kind = KIND_Y
        case (ROW_DX); service_kind = KIND_DX
        case (ROW_DY); service_kind = KIND_DY
        case (ROW_CYC); service_kind = KIND_CYC
        case (ROW_K); service_kind = KIND_K
        case (ROW_KK); service_kind = KIND_KK
        case (ROW_GM); service_kind = KIND_GM
        case default; service_kind = -1
        end select
    end function service_kind

    ! ------------------------------------------------------------------
    ! Geometry of the frame rules, in exact integer arithmetic.
    ! ------------------------------------------------------------------

    !> sqrt(q) <= sqrt(p) + 1 for 0 <= p <= 4*MAX_RADIUS**2 and q >= 0:
    !> d = q - p - 1 <= 0 or d*d <= 4*p (then d <= 4*MAX_RADIUS, no overflow).
    logical function sqrt_within(p, q)
        integer(int64), intent(in) :: p, q
        integer(int64) :: d
        d = q - p - ARC_TOLERANCE * ARC_TOLERANCE
        if (d <= 0) then
            sqrt_within = .true.
        else if (d > 4 * ARC_TOLERANCE * MAX_RADIUS + 1) then
            sqrt_within = .false.
        else
            sqrt_within = d * d <= 4 * ARC_TOLERANCE * ARC_TOLERANCE * p
        end if
    end function sqrt_within

    !> True if the arc end (x+dx, y+dy) is within one unit of the start circle
    !> of radius |(x, y)| <= MAX_RADIUS: | |end| - |start| | <= 1, exactly.
    logical function on_circle(x, y, dx, dy)
        integer(int64), intent(in) :: x, y, dx, dy
        integer(int64) :: p, q, ex, ey, lim
        lim = 2 * MAX_RADIUS + 2
        ex = x + dx
        ey = y + dy
        on_circle = .false.
        if (abs(ex) > lim .or. abs(ey) > lim) return     ! far off any legal circle
        p = x * x + y * y
        q = ex * ex + ey * ey
        if (p > MAX_RADIUS * MAX_RADIUS) return
        on_circle = sqrt_within(p, q)
        if (on_circle .and. q <= MAX_RADIUS * MAX_RADIUS * 4) on_circle = sqrt_within(q, p)
    end function on_circle

    !> The first rule (in row order) that one frame breaks: the message and the
    !> row of the field it belongs to (f%rows; the K row when the field has
    !> none). Empty message when the frame is good.
    subroutine frame_problem(f, message, row)
        type(frame_t), intent(in) :: f
        character(len=:), allocatable, intent(out) :: message
        integer, intent(out) :: row
        logical :: circular
        integer :: best
        character(len=:), allocatable :: m
        integer :: r
        message = ''
        row = 0
        best = huge(best)
        circular = f%k == 11 .or. f%k == 13
        if (f%x /= 0 .and. .not. circular) then
            call consider(1, 'X/Y only with K11/K13 (this frame is K' // k2(f%k) // ')')
        else if (f%y /= 0 .and. .not. circular) then
            call consider(2, 'X/Y only with K11/K13 (this frame is K' // k2(f%k) // ')')
        end if
        if (circular .and. (f%x /= 0 .or. f%y /= 0)) then
            if (too_big(f%x, f%y)) then
                call consider(merge(1, 2, f%x /= 0), 'radius ' // &
                    fixed(hypot(real(f%x, real64), real(f%y, real64)), 1) // &
                    ' exceeds ' // str(MAX_RADIUS) // ' units (10 m)')
            else if ((f%dx /= 0 .or. f%dy /= 0)) then
                if (.not. on_circle(f%x, f%y, f%dx, f%dy)) then
                    call consider(merge(3, 4, f%dx /= 0), &
                        'arc end point is not on the circle: start radius ' // &
                        fixed(hypot(real(f%x, real64), real(f%y, real64)), 1) // &
                        ', end radius ' // fixed(hypot(real(f%x + f%dx, real64), &
                        real(f%y + f%dy, real64)), 1) // ' (tolerance ' // &
                        str(ARC_TOLERANCE) // ' unit)')
                end if
            end if
        end if
        if (f%cyc < 0 .or. f%cyc == 1) then
            call consider(5, 'CYC ' // str(f%cyc) // ': a cycle runs its pair at least 2 times')
        end if
        if (.not. any(f%k == [10, 20, 11, 13])) then
            call consider(6, 'K ' // k2(f%k) // ' is not a command (10, 20, 11, 13)')
        else if (circular .and. f%x == 0 .and. f%y == 0) then
            call consider(6, 'K' // k2(f%k) // ' needs X or Y (the radius must be > 0)')
        end if
    contains
        subroutine consider(field, text)
            integer, intent(in) :: field
            character(len=*), intent(in) :: text
            r = f%rows(field)
            if (r == 0) r = f%rows(6)
            if (len(message) == 0 .or. r < best) then
                m = text
                message = m
                best = r
                row = r
            end if
        end subroutine consider
    end subroutine frame_problem

    logical function too_big(x, y)
        integer(int64), intent(in) :: x, y
        too_big = abs(x) > MAX_RADIUS .or. abs(y) > MAX_RADIUS
        if (.not. too_big) too_big = x * x + y * y > MAX_RADIUS * MAX_RADIUS
    end function too_big

    !> K as two digits.
    function k2(k) result(s)
        integer, intent(in) :: k
        character(len=:), allocatable :: s
        s = str(k)
        if (k >= 0 .and. k < 10) s = '0' // s
    end function k2

    ! ------------------------------------------------------------------
    ! The reader.
    ! ------------------------------------------------------------------

    !> The variant shown by the first row that tells 8 from K, and that row
    !> (0 when no row does: the two variants read the tape alike).
    subroutine scan_code(data, code, evidence)
        character(len=*), intent(in) :: data
        character(len=1), intent(out) :: code
        integer, intent(out) :: evidence
        integer :: i, d
        code = '8'
        evidence = 0
        do i = 1, len(data)
            do d = 3, 9
                if (d == 4 .or. d == 7 .or. d == 8) cycle
                if (iachar(data(i:i)) == DIGITS_8(d)) then
                    code = '8'
                    evidence = i
                    return
                else if (iachar(data(i:i)) == DIGITS_K(d)) then
                    code = 'K'
                    evidence = i
                    return
                end if
            end do
        end do
    end subroutine scan_code

    !> A reader of a tape image of n rows in code "8" or "K".
    subroutine reader_init(rd, n, code, evidence)
        type(reader_t), intent(out) :: rd
        integer, intent(in) :: n
        character(len=1), intent(in) :: code
        integer, intent(in) :: evidence
        integer :: d
        rd%n = n
        rd%code = code
        rd%evidence = evidence
        do d = 0, 9
            if (code == 'K') then
                rd%digit_of(DIGITS_K(d)) = d
            else
                rd%digit_of(DIGITS_8(d)) = d
            end if
        end do
        do d = 3, 9
            if (d == 4 .or. d == 7 .or. d == 8) cycle
            if (code == 'K') then
                rd%foreign(DIGITS_8(d)) = d
            else
                rd%foreign(DIGITS_K(d)) = d
            end if
        end do
    end subroutine reader_init

    !> The row just past the data.
    integer function end_row(rd)
        type(reader_t), intent(in) :: rd
        end_row = rd%n + 1
    end function end_row

    !> Next row with only the 5-track check; got = .false. at the end.
    subroutine raw(rd, data, got, n, value, err)
        type(reader_t), intent(inout) :: rd
        character(len=*), intent(in) :: data
        logical, intent(out) :: got
        integer, intent(out) :: n, value
        type(error_t), allocatable, intent(inout) :: err
        got = rd%i < rd%n
        n = 0
        value = 0
        if (.not. got) return
        rd%i = rd%i + 1
        n = rd%i
        value = iachar(data(n:n))
        if (value > 31 .or. value < 0) then
            call new_error(err, 'byte ' // octal3(value) // &
                ' (octal) has bits above the low 5 set (not a 5-track row: a row is 00 to 37)' // &
                trim(merge('; the file begins as text, not as a tape image', &
                           '                                              ', &
                           n == 1 .and. value >= 32 .and. value <= 126)), AT_ROW, n)
        end if
    end subroutine raw

    !> A byte in three octal digits, as the tape's own codes are named.
    function octal3(v) result(s)
        integer, intent(in) :: v
        character(len=3) :: s
        write(s, '(o3.3)') iand(v, 255)
    end function octal3

    !> Next row classified in the reader's variant; got = .false. at the end.
    subroutine next_row(rd, data, got, row, err)
        type(reader_t), intent(inout) :: rd
        character(len=*), intent(in) :: data
        logical, intent(out) :: got
        type(row_t), intent(out) :: row
        type(error_t), allocatable, intent(inout) :: err
        integer :: n, value, d
        call raw(rd, data, got, n, value, err)
        if (allocated(err) .or. .not. got) return
        row%n = n
        row%value = value
        if (rd%digit_of(value) >= 0) then
            row%kind = KIND_DIGIT
            row%digit = rd%digit_of(value)
        else if (service_kind(value) >= 0) then
            row%kind = service_kind(value)
        else if (rd%foreign(value) >= 0) then
            d = rd%foreign(value)
            if (rd%evidence > 0) then
                call new_error(err, 'mixed code: digit ' // str(d) // ' punched as ' // &
                    octal(value, 2) // ' (octal), but row ' // str(rd%evidence) // ' has ' // &
                    describe_row(iachar(data(rd%evidence:rd%evidence))) // ' of code ' // rd%code // &
                    '; one of the two is wrong: --code 8 or --code K names it', AT_ROW, n)
            else if (rd%code == 'K') then
                call new_error(err, 'parity error: digit ' // str(d) // ' punched as ' // &
                    octal(value, 2) // ', controlled code expects ' // &
                    octal(DIGITS_K(d), 2) // ' (octal)', AT_ROW, n)
            else
                call new_error(err, 'code ' // octal(value, 2) // &
                    ' (octal) is not valid in code 8 (digit ' // str(d) // &
                    ' of the controlled code K)', AT_ROW, n)
            end if
        else
            call new_error(err, 'code ' // octal(value, 2) // ' (octal) is not an EM-703 code', &
                           AT_ROW, n)
        end if
    end subroutine next_row

    !> What may follow the digits of field number last (1..5).
    function after_field(last) result(s)
        integer, intent(in) :: last
        character(len=:), allocatable :: s
        integer :: j
        s = 'digit'
        do j = last + 1, 5
            s = s // ', ' // trim(FIELD_NAME(j))
        end do
        s = s // ' or K'
    end function after_field

    !> The digits after an address; value and the row after them.
    subroutine read_number(rd, data, name, signed, value, row, err)
        type(reader_t), intent(inout) :: rd
        character(len=*), intent(in) :: data
        character(len=*), intent(in) :: name
        logical, intent(in) :: signed
        integer(int64), intent(out) :: value
        type(row_t), intent(out) :: row
        type(error_t), allocatable, intent(inout) :: err
        logical :: got, negative
        character(len=:), allocatable :: label, want
        integer :: nxt
        value = 0
        negative = .false.
        call next_row(rd, data, got, row, err)
        if (allocated(err)) return
        if (got .and. signed .and. row%kind == KIND_MINUS) then
            negative = .true.
            call next_row(rd, data, got, row, err)
            if (allocated(err)) return
        end if
        label = name
        if (negative) label = name // '-'
        if (.not. got) then
            call new_error(err, 'missing GM at the end of the tape (the tape ends after ' // &
                           label // ')', AT_ROW, end_row(rd))
            return
        end if
        if (row%kind /= KIND_DIGIT) then
            want = 'digit'
            if (signed .and. .not. negative) want = 'minus or digit'
            call new_error(err, 'expected ' // want // ' after ' // label // ', found ' // &
                           describe_row(row%value), AT_ROW, row%n)
            return
        end if
        if (row%digit == 0) then
            nxt = -1
            if (rd%i < rd%n) nxt = iachar(data(rd%i + 1:rd%i + 1))
            if (nxt >= 0 .and. nxt <= 31) then
                if (rd%digit_of(nxt) >= 0) then
                    call new_error(err, 'leading zero in ' // name // &
                                   ' (a number is punched from its first digit that is not 0)', &
                                   AT_ROW, row%n)
                    return
                end if
            end if
            call new_error(err, name // ' is 0: a zero value is never punched', AT_ROW, row%n)
            return
        end if
        do while (got .and. row%kind == KIND_DIGIT)
            if (value > (MAX_NUMBER - row%digit) / 10) then
                call new_error(err, name // ' has more than ' // str(len(str(MAX_NUMBER))) // &
                               ' digits (the largest number is ' // str(MAX_NUMBER) // ')', &
                               AT_ROW, row%n)
                return
            end if
            value = value * 10 + row%digit
            call next_row(rd, data, got, row, err)
            if (allocated(err)) return
        end do
        if (.not. got) then
            call new_error(err, 'missing GM at the end of the tape (the tape ends inside a frame)', &
                           AT_ROW, end_row(rd))
            return
        end if
        if (negative) value = -value
    end subroutine read_number

    !> One frame from its first row (not GM).
    subroutine read_frame(rd, data, first, f, err)
        type(reader_t), intent(inout) :: rd
        character(len=*), intent(in) :: data
        type(row_t), intent(in) :: first
        type(frame_t), intent(out) :: f
        type(error_t), allocatable, intent(inout) :: err
        type(row_t) :: row, nxt
        integer(int64) :: values(5), value
        integer :: last, index, ndig, digits(2), k
        logical :: got
        character(len=:), allocatable :: message, hint
        integer :: prow
        values = 0
        last = 0
        row = first
        f%row = first%n
        do while (row%kind >= KIND_X .and. row%kind <= KIND_CYC)
            index = row%kind
            if (index <= last) then
                call new_error(err, 'expected ' // after_field(last) // ' after ' // &
                    trim(FIELD_NAME(last)) // ', found ' // describe_row(row%value), AT_ROW, row%n)
                return
            end if
            f%rows(index) = row%n
            call read_number(rd, data, trim(FIELD_NAME(index)), index /= KIND_CYC, value, row, err)
            if (allocated(err)) return
            if (index == KIND_CYC .and. value < 2) then
                call new_error(err, 'CYC ' // str(value) // &
                    ': a cycle runs its pair at least 2 times', AT_ROW, f%rows(index))
                return
            end if
            values(index) = value
            last = index
            if (.not. (row%kind >= KIND_X .and. row%kind <= KIND_K)) then
                call new_error(err, 'expected ' // after_field(last) // ' after ' // &
                    trim(FIELD_NAME(last)) // ', found ' // describe_row(row%value), AT_ROW, row%n)
                return
            end if
        end do
        if (row%kind /= KIND_K) then
            hint = ''
            if (row%value == 0) hint = ' (a blank row: is the closing GM missing?)'
            call new_error(err, 'expected X, Y, DX, DY, CYC, K or GM at the start of a ' // &
                'frame, found ' // describe_row(row%value) // hint, AT_ROW, row%n)
            return
        end if
        f%rows(6) = row%n
        ndig = 0
        k = 0
        do
            call next_row(rd, data, got, nxt, err)
            if (allocated(err)) return
            if (.not. got) then
                call new_error(err, 'missing GM at the end of the tape ' // &
                    '(the tape ends inside a frame)', AT_ROW, end_row(rd))
                return
            end if
            if (nxt%kind /= KIND_DIGIT .or. ndig == 2) then
                if (nxt%kind == KIND_DIGIT .or. ndig < 2) then
                    call new_error(err, 'K must be followed by exactly two digits, found ' // &
                                   describe_row(nxt%value), AT_ROW, nxt%n)
                    return
                end if
                exit
            end if
            ndig = ndig + 1
            digits(ndig) = nxt%digit
            if (ndig == 2) then
                k = digits(1) * 10 + digits(2)
                if (.not. any(k == [10, 20, 11, 13])) then
                    call new_error(err, 'K ' // k2(k) // ' is not a command (10, 20, 11, 13)', &
                                   AT_ROW, f%rows(6))
                    return
                end if
            end if
        end do
        if (nxt%kind /= KIND_KK) then
            call new_error(err, 'expected KK after K' // k2(k) // ', found ' // &
                           describe_row(nxt%value), AT_ROW, nxt%n)
            return
        end if
        f%x = values(1)
        f%y = values(2)
        f%dx = values(3)
        f%dy = values(4)
        f%cyc = values(5)
        f%k = k
        call frame_problem(f, message, prow)
        if (len(message) > 0) call new_error(err, message, AT_ROW, prow)
    end subroutine read_frame

    !> Decode a tape image (bytes 0..255); code is "8", "K" or "auto". In
    !> "auto" the variant is the one shown by the first digit row that tells
    !> them apart, and a later row of the other variant is a "mixed code"
    !> error; a tape without such a row reads alike in both and is reported as
    !> "8" with tape%told false. On error, tape holds the frames read so far.
    subroutine decode_tape(rows, code, tape, err)
        integer, intent(in) :: rows(:)
        character(len=*), intent(in) :: code
        type(tape_t), intent(out) :: tape
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: data
        integer :: i, st
        allocate(character(len=size(rows)) :: data, stat=st)
        if (st /= 0) call no_memory('the tape', int(size(rows), int64))
        do i = 1, size(rows)
            data(i:i) = achar(iand(rows(i), 255))
            ! a row that is not a byte keeps its fault: bits above the low 5
            if (rows(i) < 0 .or. rows(i) > 255) data(i:i) = achar(255)
        end do
        call decode_bytes(data, code, tape, err)
    end subroutine decode_tape

    !> decode_tape of a tape image held as bytes (a byte a row), as read from
    !> its file. Every frame is kept (tape%frames): for a tape of any length
    !> use the decoder (decoder_start, next_frame), which holds one frame.
    subroutine decode_bytes(data, code, tape, err)
        character(len=*), intent(in) :: data
        character(len=*), intent(in) :: code
        type(tape_t), intent(out) :: tape
        type(error_t), allocatable, intent(out) :: err
        type(decoder_t) :: dec
        type(frame_t) :: f
        logical :: got
        allocate(tape%frames(16))
        call decoder_start(dec, data, code, err)
        tape%nrows = len(data)
        tape%code = dec%code
        tape%told = dec%told
        tape%opened = dec%opened
        if (allocated(err)) return
        do
            call next_frame(dec, data, f, got, err)
            if (allocated(err) .or. .not. got) exit
            call push(tape, f)
        end do
    end subroutine decode_bytes

    !> Start reading a tape image (bytes 0..255, a byte a row) frame by frame;
    !> code is "8", "K" or "auto" (decode_tape). Reads the leader up to the
    !> opening GM; err when there is none.
    subroutine decoder_start(dec, data, code, err, evidence)
        type(decoder_t), intent(out) :: dec
        character(len=*), intent(in) :: data
        character(len=*), intent(in) :: code
        type(error_t), allocatable, intent(out) :: err
        !> a second reading of a tape whose variant "auto" told: the row that
        !> told it (decoder_t's evidence), so its faults read as the first did
        integer, intent(in), optional :: evidence
        logical :: got
        integer :: n, value, told_at
        character(len=1) :: c
        dec%nrows = len(data)
        dec%done = .true.
        told_at = 0
        select case (code)
        case ('8', 'K')
            c = code
            dec%told = .true.
            if (present(evidence)) told_at = evidence
        case ('auto')
            call scan_code(data, c, told_at)
            dec%told = told_at > 0
        case default
            call new_error(err, 'code must be 8, K or auto, not "' // code // '"')
            return
        end select
        dec%code = c
        dec%evidence = told_at
        call reader_init(dec%rd, len(data), c, told_at)

        ! Leader: blank rows up to the opening GM.
        do
            call raw(dec%rd, data, got, n, value, err)
            if (allocated(err)) return
            if (.not. got) then
                if (len(data) == 0) then
                    call new_error(err, 'missing GM at the start of the tape (the tape is empty)', &
                                   AT_ROW, end_row(dec%rd))
                else
                    call new_error(err, 'missing GM at the start of the tape (only blank rows)', &
                                   AT_ROW, end_row(dec%rd))
                end if
                return
            end if
            if (value == ROW_GM) then
                dec%opened = .true.
                exit
            end if
            if (value /= ROW_BLANK) then
                call new_error(err, 'data before the opening GM: found ' // describe_row(value), &
                               AT_ROW, n)
                return
            end if
        end do
        dec%done = .false.
    end subroutine decoder_start

    !> The next frame of the tape (data: the same image as decoder_start's);
    !> got = .false. after the closing GM, once the trailer is found blank.
    !> The first error stops the decoder: err names its row.
    subroutine next_frame(dec, data, f, got, err)
        type(decoder_t), intent(inout) :: dec
        character(len=*), intent(in) :: data
        type(frame_t), intent(out) :: f
        logical, intent(out) :: got
        type(error_t), allocatable, intent(out) :: err
        type(row_t) :: row
        integer :: n, value
        got = .false.
        if (dec%done) return
        dec%done = .true.
        call next_row(dec%rd, data, got, row, err)
        if (allocated(err)) then
            got = .false.
            return
        end if
        if (.not. got) then
            call new_error(err, 'missing GM at the end of the tape', AT_ROW, end_row(dec%rd))
            return
        end if
        if (row%kind == KIND_GM) then
            got = .false.
            if (dec%opener_row > 0) then
                call new_error(err, 'CYC needs a following frame (CYC on the last frame)', &
                               AT_ROW, dec%opener_row)
                return
            end if
            ! Trailer: blank rows only.
            do
                call raw(dec%rd, data, got, n, value, err)
                if (allocated(err) .or. .not. got) exit
                if (value /= ROW_BLANK) then
                    call new_error(err, 'data after the closing GM: found ' // describe_row(value), &
                                   AT_ROW, n)
                    exit
                end if
            end do
            got = .false.
            return
        end if
        got = .false.
        call read_frame(dec%rd, data, row, f, err)
        if (allocated(err)) return
        if (dec%opener_row > 0) then
            if (f%cyc /= 0) then
                call new_error(err, 'CYC on the second frame of a cycle pair (its CYC is at row ' &
                               // str(dec%opener_row) // ')', AT_ROW, f%rows(5))
                return
            end if
            dec%opener_row = 0
        else if (f%cyc /= 0) then
            dec%opener_row = f%rows(5)
        end if
        dec%nframes = dec%nframes + 1
        dec%done = .false.
        got = .true.
    end subroutine next_frame

    subroutine push(tape, f)
        type(tape_t), intent(inout) :: tape
        type(frame_t), intent(in) :: f
        type(frame_t), allocatable :: bigger(:)
        integer :: st
        if (tape%nframes == size(tape%frames)) then
            allocate(bigger(2 * size(tape%frames)), stat=st)
            if (st /= 0) call no_memory('the frames of the tape', &
                int(2 * size(tape%frames), int64) * storage_size(f) / 8)
            bigger(1:tape%nframes) = tape%frames(1:tape%nframes)
            call move_alloc(bigger, tape%frames)
        end if
        tape%nframes = tape%nframes + 1
        tape%frames(tape%nframes) = f
    end subroutine push

    ! ------------------------------------------------------------------
    ! Encoder.
    ! ------------------------------------------------------------------

    !> The rows of one frame in code "8" or "K" (no checks).
    subroutine frame_rows(f, code, rows, n)
        type(frame_t), intent(in) :: f
        character(len=1), intent(in) :: code
        integer, intent(inout) :: rows(:)    !< at least 70 free places from n+1
        integer, intent(inout) :: n          !< rows in use
        call number(ROW_X, f%x)
        call number(ROW_Y, f%y)
        call number(ROW_DX, f%dx)
        call number(ROW_DY, f%dy)
        call number(ROW_CYC, f%cyc)
        call put(ROW_K)
        call digits(int(f%k, int64), 2)
        call put(ROW_KK)
    contains
        subroutine put(v)
            integer, intent(in) :: v
            n = n + 1
            rows(n) = v
        end subroutine put
        subroutine number(address, v)
            integer, intent(in) :: address
            integer(int64), intent(in) :: v
            if (v == 0) return
            call put(address)
            if (v < 0) call put(ROW_MINUS)
            call digits(abs(v), 1)
        end subroutine number
        subroutine digits(v, width)
            integer(int64), intent(in) :: v
            integer, intent(in) :: width
            character(len=24) :: buf
            integer :: j, d
            write(buf, '(i0)') v
            do j = len_trim(buf) + 1, width
                call put(digit_row(0))
            end do
            do j = 1, len_trim(buf)
                d = iachar(buf(j:j)) - iachar('0')
                call put(digit_row(d))
            end do
        end subroutine digits
        integer function digit_row(d)
            integer, intent(in) :: d
            if (code == 'K') then
                digit_row = DIGITS_K(d)
            else
                digit_row = DIGITS_8(d)
            end if
        end function digit_row
    end subroutine frame_rows

    !> A tape image: leader blank rows, GM, the frames, GM, leader blank rows.
    !> The frames are checked first (each frame's rules, and a CYC needs a
    !> following frame that has none); err names the frame (line = frame).
    subroutine encode_tape(frames, code, leader, rows, err)
        type(frame_t), intent(in) :: frames(:)
        character(len=1), intent(in) :: code
        integer, intent(in) :: leader
        integer, allocatable, intent(out) :: rows(:)
        type(error_t), allocatable, intent(out) :: err
        integer, allocatable :: buf(:)
        integer :: i, n, r, st
        character(len=:), allocatable :: message
        type(frame_t) :: f
        logical :: opener
        if (code /= '8' .and. code /= 'K') then
            call new_error(err, 'code must be 8 or K, not "' // code // '"')
            return
        end if
        opener = .false.
        do i = 1, size(frames)
            f = frames(i)
            f%rows = 0
            f%rows(6) = 1
            call frame_problem(f, message, r)
            if (len(message) > 0) then
                call new_error(err, 'frame ' // str(i) // ': ' // message)
                return
            end if
            if (opener) then
                if (f%cyc /= 0) then
                    call new_error(err, 'frame ' // str(i) // ': CYC on the second frame of a cycle pair')
                    return
                end if
                opener = .false.
            else
                opener = f%cyc /= 0
            end if
            if (abs(f%x) > MAX_NUMBER .or. abs(f%y) > MAX_NUMBER .or. abs(f%dx) > MAX_NUMBER &
                .or. abs(f%dy) > MAX_NUMBER .or. f%cyc > MAX_NUMBER) then
                call new_error(err, 'frame ' // str(i) // ': a number has more than 9 digits')
                return
            end if
        end do
        if (opener) then
            call new_error(err, 'frame ' // str(size(frames)) // ': CYC needs a following frame')
            return
        end if
        allocate(buf(2 * leader + 2 + 70 * size(frames)), stat=st)
        if (st /= 0) call no_memory('the tape image', 4 * (2 * leader + 2 + 70 * int(size(frames), int64)))
        buf = ROW_BLANK
        n = leader + 1
        buf(n) = ROW_GM
        do i = 1, size(frames)
            call frame_rows(frames(i), code, buf, n)
        end do
        n = n + 1
        buf(n) = ROW_GM
        n = n + leader
        rows = buf(1:n)
    end subroutine encode_tape

    ! ------------------------------------------------------------------
    ! Frame text (docs/FILES.md: the NAME-*.txt files).
    ! ------------------------------------------------------------------

    !> One frame as text, e.g. "DX300 DY400 CYC8 K10 KK"; utf8 gives the
    !> report's symbols ΔX ΔY Ц К КК.
    function frame_text(f, utf8) result(s)
        type(frame_t), intent(in) :: f
        logical, intent(in) :: utf8
        character(len=:), allocatable :: s
        s = ''
        if (f%x /= 0) s = s // 'X' // str(f%x) // ' '
        if (f%y /= 0) s = s // 'Y' // str(f%y) // ' '
        if (f%dx /= 0) s = s // name_of(3) // str(f%dx) // ' '
        if (f%dy /= 0) s = s // name_of(4) // str(f%dy) // ' '
        if (f%cyc /= 0) s = s // name_of(5) // str(f%cyc) // ' '
        s = s // name_of(6) // k2(f%k) // ' ' // name_of(7)
    contains
        function name_of(field) result(t)
            integer, intent(in) :: field
            character(len=:), allocatable :: t
            if (.not. utf8) then
                select case (field)
                case (3); t = 'DX'
                case (4); t = 'DY'
                case (5); t = 'CYC'
                case (6); t = 'K'
                case default; t = 'KK'
                end select
            else
                select case (field)
                case (3); t = delta() // 'X'
                case (4); t = delta() // 'Y'
                case (5); t = char(208) // char(166)                  ! Ц
                case (6); t = char(208) // char(154)                  ! К
                case default; t = char(208) // char(154) // char(208) // char(154)  ! КК
                end select
            end if
        end function name_of
        function delta() result(t)
            character(len=2) :: t
            t = char(206) // char(148)                                ! Δ
        end function delta
    end function frame_text

    !> GM line, one line per frame, GM line (ГМ with utf8), each with a newline.
    subroutine tape_text(frames, utf8, text)
        type(frame_t), intent(in) :: frames(:)
        logical, intent(in) :: utf8
        type(text_t), intent(inout) :: text
        integer :: i
        character(len=:), allocatable :: gm
        gm = 'GM'
        if (utf8) gm = char(208) // char(147) // char(208) // char(156)   ! ГМ
        call text%add(gm)
        do i = 1, size(frames)
            call text%add(frame_text(frames(i), utf8))
        end do
        call text%add(gm)
    end subroutine tape_text

end module em703_codec
