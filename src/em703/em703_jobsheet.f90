!> The job sheet TENZOR writes beside the tapes of a package (docs/FILES.md):
!> `key = value` lines, `#` comment lines. The em703 tools read the name, the
!> job's own name (html's heading), the code, the scale, the start point and, for each tape T in small, large,
!> cond, its file `T.tape` (relative to the job sheet's directory) and its
!> tool `T.tool_mm`, and when TENZOR recorded them, its size `T.bytes` and
!> SHA-256 `T.sha256`, which the tools check. Other keys are ignored.
module em703_jobsheet
    use, intrinsic :: iso_fortran_env, only: int64
    use base_error, only: error_t, new_error, AT_LINE
    use base_io, only: read_text, dir_of
    use base_text, only: parse_int, parse_mm
    use em703_sim, only: FIELD_UNITS
    implicit none
    private
    public :: job_t, layer_t, read_job, parse_scale, machine_scale, LAYER_KEYS, NLAYERS

    integer, parameter :: NLAYERS = 3
    character(len=5), parameter :: LAYER_KEYS(NLAYERS) = ['small', 'large', 'cond ']

    !> One tape of a job: its key, the file as named and as a path, its tool.
    type :: layer_t
        character(len=:), allocatable :: key
        character(len=:), allocatable :: tape     !< as on the job sheet
        character(len=:), allocatable :: path     !< relative to the working directory
        integer(int64) :: tool = 0                !< tool diameter, 0.01 mm
        integer(int64) :: bytes = -1              !< T.bytes: the tape's size (-1: not given)
        character(len=:), allocatable :: sha256   !< T.sha256: its SHA-256 ("": not given)
    end type layer_t

    type :: job_t
        character(len=:), allocatable :: path
        character(len=:), allocatable :: name
        character(len=:), allocatable :: title    !< the job's name (key job; "" without one)
        character(len=:), allocatable :: code     !< "8", "K" or "auto" (no code line)
        integer :: num = 1, den = 1               !< scale num:den
        integer(int64) :: start_x = 0, start_y = 0  !< start point on the field, 0.01 mm
        type(layer_t) :: layers(NLAYERS)
    end type job_t

contains

    !> Read and check a job sheet. Errors name the line (or the missing key).
    subroutine read_job(path, job, err)
        character(len=*), intent(in) :: path
        type(job_t), intent(out) :: job
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: text, line, key, value
        integer :: i, j, lineno, p, l, c
        character(len=3) :: octal
        logical :: seen_tape(NLAYERS), seen_tool(NLAYERS), ok
        integer(int64) :: v

        job%path = path
        job%name = ''
        job%title = ''
        job%code = 'auto'
        do l = 1, NLAYERS
            job%layers(l)%key = trim(LAYER_KEYS(l))
            job%layers(l)%tape = ''
            job%layers(l)%path = ''
            job%layers(l)%sha256 = ''
        end do
        seen_tape = .false.
        seen_tool = .false.
        call read_text(path, text, err)
        if (allocated(err)) return

        i = 1
        lineno = 0
        do while (i <= len(text))
            j = index(text(i:), achar(10))
            if (j == 0) then
                line = text(i:)
                i = len(text) + 1
            else
                line = text(i:i + j - 2)
                i = i + j
            end if
            lineno = lineno + 1
            if (len(line) > 0) then
                if (line(len(line):) == achar(13)) line = line(1:len(line) - 1)
            end if
            do p = 1, len(line)
                c = iachar(line(p:p))
                if ((c < 32 .and. c /= 9) .or. c > 126) then
                    write(octal, '(o3.3)') c
                    call new_error(err, 'byte ' // octal // ' (octal) is not text: a job ' // &
                                   'sheet is the text NAME.job that TENZOR writes beside ' // &
                                   'the tapes (a tape is read by em703 list)', AT_LINE, lineno, p)
                    err%file = path
                    return
                end if
            end do
            if (len_trim(line) == 0) cycle
            if (line(1:1) == '#') cycle
            p = index(line, ' = ')
            if (p == 0) then
                if (len(line) > 60) line = line(1:60) // '...'
                call fail('not a "key = value" line: "' // line // '"')
                return
            end if
            key = trim(adjustl(line(1:p - 1)))
            value = trim(adjustl(line(p + 3:)))
            select case (key)
            case ('name')
                job%name = value
            case ('job')
                job%title = value
            case ('code')
                if (value /= '8' .and. value /= 'K') then
                    call fail('code must be 8 or K, not "' // value // '"')
                    return
                end if
                job%code = value
            case ('scale')
                call parse_scale(value, job%num, job%den, ok)
                if (ok) ok = machine_scale(job%num, job%den)
                if (.not. ok) then
                    call fail('scale must be one of the machine''s scales 1:100 1:10 1:5 1:2 ' // &
                              '1:1 2:1 5:1 50:1 100:1, not "' // value // '"')
                    return
                end if
            case ('start_x_mm', 'start_y_mm')
                call parse_mm(value, v, ok)
                if (ok) ok = v >= 0 .and. v <= FIELD_UNITS
                if (.not. ok) then
                    call fail(key // ' must be a place on the field, 0.00 to 1200.00 mm (two ' // &
                              'decimals at most), not "' // value // '"')
                    return
                end if
                if (key == 'start_x_mm') then
                    job%start_x = v
                else
                    job%start_y = v
                end if
            case default
                do l = 1, NLAYERS
                    if (key == trim(LAYER_KEYS(l)) // '.tape') then
                        if (len(value) == 0 .or. index(value, '/') > 0) then
                            call fail(key // ' must name a file beside the job sheet, not "' // &
                                      value // '"')
                            return
                        end if
                        job%layers(l)%tape = value
                        job%layers(l)%path = dir_of(path) // value
                        seen_tape(l) = .true.
                    else if (key == trim(LAYER_KEYS(l)) // '.tool_mm') then
                        call parse_mm(value, v, ok)
                        if (.not. ok .or. v <= 0 .or. v > FIELD_UNITS) then
                            call fail(key // ' must be a tool width in mm (above 0, at most ' // &
                                      '1200.00, the field; two decimals), ' // &
                                      'not "' // value // '"')
                            return
                        end if
                        job%layers(l)%tool = v
                        seen_tool(l) = .true.
                    else if (key == trim(LAYER_KEYS(l)) // '.bytes') then
                        call parse_int(value, v, ok)
                        if (.not. ok .or. v < 0) then
                            call fail(key // ' must be a size in bytes, not "' // value // '"')
                            return
                        end if
                        job%layers(l)%bytes = v
                    else if (key == trim(LAYER_KEYS(l)) // '.sha256') then
                        if (len(value) /= 64 .or. verify(value, '0123456789abcdef') /= 0) then
                            call fail(key // ' must be 64 lower-case hexadecimal digits, not "' &
                                      // value // '"')
                            return
                        end if
                        job%layers(l)%sha256 = value
                    end if
                end do
            end select
        end do
        if (len(job%name) == 0) then
            call new_error(err, 'the job sheet has no "name = ..." line')
            err%file = path
            return
        end if
        do l = 1, NLAYERS
            if (.not. seen_tape(l)) then
                call new_error(err, 'the job sheet has no "' // trim(LAYER_KEYS(l)) // &
                               '.tape = ..." line')
            else if (.not. seen_tool(l)) then
                call new_error(err, 'the job sheet has no "' // trim(LAYER_KEYS(l)) // &
                               '.tool_mm = ..." line')
            end if
            if (allocated(err)) then
                err%file = path
                return
            end if
        end do
    contains
        subroutine fail(message)
            character(len=*), intent(in) :: message
            call new_error(err, message, AT_LINE, lineno)
            err%file = path
        end subroutine fail
    end subroutine read_job

    !> "N:D" with 1 <= N, D <= 100.
    subroutine parse_scale(s, num, den, ok)
        character(len=*), intent(in) :: s
        integer, intent(out) :: num, den
        logical, intent(out) :: ok
        integer :: p
        integer(int64) :: a, b
        num = 1
        den = 1
        ok = .false.
        p = index(s, ':')
        if (p == 0) return
        call parse_int(s(1:p - 1), a, ok)
        if (.not. ok) return
        call parse_int(s(p + 1:), b, ok)
        if (.not. ok) return
        ok = a >= 1 .and. a <= 100 .and. b >= 1 .and. b <= 100
        if (ok) then
            num = int(a)
            den = int(b)
        end if
    end subroutine parse_scale

    !> True for the scales the machine has (the report's description of it): 1:100, 1:10, 1:5,
    !> 1:2, 1:1, 2:1, 5:1, 50:1, 100:1 (10:1 is not in the report's list).
    logical function machine_scale(num, den)
        integer, intent(in) :: num, den
        machine_scale = (num == 1 .and. any(den == [1, 2, 5, 10, 100])) .or. &
                        (den == 1 .and. any(num == [2, 5, 50, 100]))
    end function machine_scale

end module em703_jobsheet
