!> File input and output of the modern tools: a whole file as text, a file
!> written whole or not at all (base_files: a fresh temporary file, fsynced,
!> renamed; a failed run never leaves half a file), a message on standard
!> error. (Long outputs are streamed by base_text's text_t attached to a
!> file of base_files' open_out, or to standard output.) Failures come back
!> as an error_t naming the file.
module base_io
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use base_error, only: error_t, new_error, no_memory
    use base_files, only: write_whole, read_whole
    implicit none
    private
    public :: read_text, write_bytes, write_text, dir_of, say

contains

    !> The whole file as one string (bytes as characters).
    subroutine read_text(path, text, err)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: text
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: msg
        logical :: exists
        inquire(file=path, exist=exists)
        if (.not. exists) then
            text = ''
            call new_error(err, 'cannot open: no such file')
            err%file = path
            return
        end if
        call read_whole(path, text, msg)
        if (len(msg) > 0) then
            call new_error(err, msg)
            err%file = path
        end if
    end subroutine read_text

    !> Write bytes (values 0..255) as a file.
    subroutine write_bytes(path, rows, err)
        character(len=*), intent(in) :: path
        integer, intent(in) :: rows(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: text
        integer :: i, st
        allocate(character(len=size(rows)) :: text, stat=st)
        if (st /= 0) call no_memory('the tape', int(size(rows), int64))
        do i = 1, size(rows)
            text(i:i) = achar(iand(rows(i), 255))
        end do
        call write_text(path, text, err)
    end subroutine write_bytes

    !> Write a string as the whole file, or not at all (base_files): a failure
    !> leaves the file as it was.
    subroutine write_text(path, text, err)
        character(len=*), intent(in) :: path
        character(len=*), intent(in) :: text
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: msg
        call write_whole(path, text, msg)
        if (len(msg) > 0) then
            call new_error(err, 'cannot write: ' // msg)
            err%file = path
        end if
    end subroutine write_text

    !> The directory part of a path with its slash ("" for a bare name).
    function dir_of(path) result(dir)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: dir
        integer :: k
        k = index(path, '/', back=.true.)
        dir = path(1:k)
    end function dir_of

    !> One line on standard error (the programs' messages).
    subroutine say(line)
        character(len=*), intent(in) :: line
        integer :: ios
        write(error_unit, '(a)', iostat=ios) line
    end subroutine say

end module base_io
