!> The few operating-system services Fortran lacks: make a directory, rename a
!> file atomically, remove a file, read a file descriptor to its end byte for
!> byte. Thin bindings to the C library.
module base_os
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_size_t, c_long
    use, intrinsic :: iso_fortran_env, only: int64
    use base_error, only: no_memory
    implicit none
    private
    public :: make_dirs, rename_file, remove_file, is_dir, read_fd

    interface
        function c_mkdir(path, mode) bind(c, name='mkdir') result(rc)
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), value :: mode
            integer(c_int) :: rc
        end function c_mkdir
        function c_rename(old, new) bind(c, name='rename') result(rc)
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: old(*), new(*)
            integer(c_int) :: rc
        end function c_rename
        function c_remove(path) bind(c, name='remove') result(rc)
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int) :: rc
        end function c_remove
        !> POSIX read(2); ssize_t is a C long on the platforms gfortran serves.
        function c_read(fd, buf, count) bind(c, name='read') result(n)
            import :: c_int, c_char, c_size_t, c_long
            integer(c_int), value :: fd
            character(kind=c_char), intent(out) :: buf(*)
            integer(c_size_t), value :: count
            integer(c_long) :: n
        end function c_read
    end interface

contains

    !> Create a directory and its missing parents (like `mkdir -p`).
    !> ok is false when the last component does not exist afterwards as a directory.
    subroutine make_dirs(path, ok)
        character(len=*), intent(in) :: path
        logical, intent(out) :: ok
        integer :: i, rc
        do i = 2, len(path)
            if (path(i:i) == '/') rc = c_mkdir(path(1:i-1) // c_null_char, int(o'777', c_int))
        end do
        rc = c_mkdir(path // c_null_char, int(o'777', c_int))
        ok = is_dir(path)
    end subroutine make_dirs

    !> Read file descriptor fd to its end, exactly as the bytes come (no record
    !> or line-end processing, so a pipe, a FIFO and standard input read like a
    !> regular file). istat: 0 done; 1 read(2) failed (a directory, an I/O
    !> error); 2 more than max_bytes.
    subroutine read_fd(fd, max_bytes, data, istat)
        integer, intent(in) :: fd, max_bytes
        character(len=:), allocatable, intent(out) :: data
        integer, intent(out) :: istat
        integer, parameter :: chunk = 65536
        character(len=chunk) :: buf
        character(len=:), allocatable :: tmp
        integer :: n, have, st
        integer(c_long) :: got
        allocate(character(len=chunk) :: data)
        have = 0
        do
            got = c_read(int(fd, c_int), buf, int(chunk, c_size_t))
            if (got < 0) then
                istat = 1
                return
            end if
            if (got == 0) exit
            n = int(got)
            if (n > max_bytes - have) then
                istat = 2
                return
            end if
            if (have + n > len(data)) then
                allocate(character(len=len(data) + min(len(data), max_bytes - len(data))) :: tmp, &
                         stat=st)
                if (st /= 0) call no_memory('the input', 2 * int(len(data), int64))
                tmp(1:have) = data(1:have)
                call move_alloc(tmp, data)
            end if
            data(have + 1:have + n) = buf(1:n)
            have = have + n
        end do
        data = data(1:have)
        istat = 0
    end subroutine read_fd

    !> True when path names an existing directory.
    logical function is_dir(path)
        character(len=*), intent(in) :: path
        inquire(file=path // '/.', exist=is_dir)
    end function is_dir

    !> Rename old to new, replacing new; ok is false on failure.
    subroutine rename_file(old, new, ok)
        character(len=*), intent(in) :: old, new
        logical, intent(out) :: ok
        ok = c_rename(old // c_null_char, new // c_null_char) == 0
    end subroutine rename_file

    !> Remove a file if it exists; failures are ignored.
    subroutine remove_file(path)
        character(len=*), intent(in) :: path
        integer :: rc
        rc = c_remove(path // c_null_char)
    end subroutine remove_file

end module base_os
