!> The error of the modern tools: which file, where in it (a tape row, a text
!> line and column, or nowhere in particular) and what was expected.
!>
!> A routine that can fail has an argument `type(error_t), allocatable,
!> intent(out) :: err`; it is allocated only when the routine failed (the
!> convention of fpm's error type). `error_text` turns it into the one line
!> the command prints on standard error: `FILE: row N: message`.
module base_error
    implicit none
    private
    public :: error_t, new_error, error_text, set_file, no_memory

    !> Where the error is: nowhere, a row of a tape (1 = first byte), or a
    !> line (and column, 0 = the whole line) of a text file.
    integer, parameter, public :: AT_NONE = 0, AT_ROW = 1, AT_LINE = 2

    type :: error_t
        character(len=:), allocatable :: file      !< file name, may be empty
        integer :: at = AT_NONE                    !< AT_NONE, AT_ROW or AT_LINE
        integer :: number = 0                      !< the row or the line
        integer :: column = 0                      !< column of a line, 0 = none
        character(len=:), allocatable :: message   !< what was found and expected
    end type error_t

contains

    !> Allocate err with a message and its place (file is set later by the caller
    !> who knows it, see set_file).
    subroutine new_error(err, message, at, number, column)
        type(error_t), allocatable, intent(inout) :: err
        character(len=*), intent(in) :: message
        integer, intent(in), optional :: at, number, column
        if (allocated(err)) deallocate(err)
        allocate(err)
        err%file = ''
        err%message = message
        if (present(at)) err%at = at
        if (present(number)) err%number = number
        if (present(column)) err%column = column
    end subroutine new_error

    !> Name the file of an error (when it is allocated and has no file yet).
    subroutine set_file(err, file)
        type(error_t), allocatable, intent(inout) :: err
        character(len=*), intent(in) :: file
        if (.not. allocated(err)) return
        if (len(err%file) == 0) err%file = file
    end subroutine set_file

    !> One line: `FILE: row N: message`, `FILE: line N, column C: message`,
    !> `FILE: message`, or the message alone when there is no file.
    function error_text(err) result(text)
        type(error_t), intent(in) :: err
        character(len=:), allocatable :: text
        character(len=24) :: n, c
        text = ''
        if (allocated(err%file)) then
            if (len(err%file) > 0) text = err%file // ': '
        end if
        write(n, '(i0)') err%number
        write(c, '(i0)') err%column
        select case (err%at)
        case (AT_ROW)
            text = text // 'row ' // trim(n) // ': '
        case (AT_LINE)
            text = text // 'line ' // trim(n)
            if (err%column > 0) text = text // ', column ' // trim(c)
            text = text // ': '
        end select
        if (allocated(err%message)) text = text // err%message
    end function error_text

    !> Memory that cannot be had ends the run with a message and exit status
    !> 2, never with the Fortran runtime's allocation error: every allocate
    !> whose size comes from the input has stat= and calls this on failure.
    !> what says what the memory was for; nbytes about how much was asked.
    subroutine no_memory(what, nbytes)
        use, intrinsic :: iso_fortran_env, only: error_unit, int64
        character(len=*), intent(in) :: what
        integer(int64), intent(in) :: nbytes
        character(len=4096) :: prog
        character(len=24) :: num
        integer :: n, ios
        call get_command_argument(0, prog, n)
        n = index(prog, '/', back=.true.)
        write(num, '(i0)') max(1_int64, nbytes / 1048576_int64)
        write(error_unit, '(a)', iostat=ios) trim(prog(n + 1:)) // ': not enough memory for ' // &
            what // ' (about ' // trim(num) // ' MB more); no half-made output is left'
        stop 2, quiet=.true.
    end subroutine no_memory

end module base_error
