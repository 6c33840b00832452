!> The few operating-system services Fortran lacks: make a directory, rename a
!> file atomically, remove a file. Thin bindings to the C library.
module em703_os
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
    implicit none
    private
    public :: make_dirs, rename_file, remove_file

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

end module em703_os
