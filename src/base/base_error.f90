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
    public :: error_t, new_error, error_text, set_file

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

end module base_error
