!> Whole-file output: every file a program writes is written whole or not at
!> all (base_files.c does the system calls). A new file goes to a temporary
!> name beside its target, created exclusively (never an existing name, never
!> through a planted symbolic link), is written in full, fsynced, and renamed
!> over the target; a failure leaves the target as it was and no temporary
!> file. A set of files (a TENZOR package) is staged first and renamed
!> together, under the directory's lock, so that runs into one directory never
!> mix their files. A target that is a device or a FIFO (/dev/stdout) is
!> written straight into.
module base_files
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_size_t, c_long_long
    implicit none
    private
    public :: write_whole, commit_file, sync_dir_of, discard_file
    public :: lock_dir, unlock_dir, same_file, read_whole
    public :: open_out, write_out, write_back, close_out

    interface
        function c_commit(tmp, path, sync_dir) bind(c, name='em_commit') result(rc)
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: tmp(*), path(*)
            integer(c_int), value :: sync_dir
            integer(c_int) :: rc
        end function c_commit
        subroutine c_sync_dir(path) bind(c, name='em_sync_dir')
            import :: c_char
            character(kind=c_char), intent(in) :: path(*)
        end subroutine c_sync_dir
        subroutine c_discard(tmp) bind(c, name='em_discard')
            import :: c_char
            character(kind=c_char), intent(in) :: tmp(*)
        end subroutine c_discard
        function c_lock(dir, fd) bind(c, name='em_lock') result(rc)
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: dir(*)
            integer(c_int), intent(out) :: fd
            integer(c_int) :: rc
        end function c_lock
        subroutine c_unlock(fd) bind(c, name='em_unlock')
            import :: c_int
            integer(c_int), value :: fd
        end subroutine c_unlock
        function c_same_file(a, b) bind(c, name='em_same_file') result(rc)
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: a(*), b(*)
            integer(c_int) :: rc
        end function c_same_file
        function c_open_read(path, fd, size) bind(c, name='em_open_read') result(rc)
            import :: c_int, c_char, c_long_long
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), intent(out) :: fd
            integer(c_long_long), intent(out) :: size
            integer(c_int) :: rc
        end function c_open_read
        function c_read(fd, buf, cap) bind(c, name='em_read') result(n)
            import :: c_int, c_char, c_size_t, c_long_long
            integer(c_int), value :: fd
            character(kind=c_char), intent(inout) :: buf(*)
            integer(c_size_t), value :: cap
            integer(c_long_long) :: n
        end function c_read
        subroutine c_close_read(fd) bind(c, name='em_close_read')
            import :: c_int
            integer(c_int), value :: fd
        end subroutine c_close_read
        function c_open_out(path, fd, tmp, cap) bind(c, name='em_open_out') result(rc)
            import :: c_int, c_char, c_size_t
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), intent(out) :: fd
            character(kind=c_char), intent(out) :: tmp(*)
            integer(c_size_t), value :: cap
            integer(c_int) :: rc
        end function c_open_out
        function c_write(fd, data, n) bind(c, name='em_write') result(rc)
            import :: c_int, c_char, c_size_t
            integer(c_int), value :: fd
            character(kind=c_char), intent(in) :: data(*)
            integer(c_size_t), value :: n
            integer(c_int) :: rc
        end function c_write
        subroutine c_write_back(fd) bind(c, name='em_write_back')
            import :: c_int
            integer(c_int), value :: fd
        end subroutine c_write_back
        function c_close_out(fd, tmp, total) bind(c, name='em_close_out') result(rc)
            import :: c_int, c_char, c_long_long
            integer(c_int), value :: fd
            character(kind=c_char), intent(in) :: tmp(*)
            integer(c_long_long), value :: total
            integer(c_int) :: rc
        end function c_close_out
        subroutine c_strerror(rc, msg, cap) bind(c, name='em_strerror')
            import :: c_int, c_char, c_size_t
            integer(c_int), value :: rc
            character(kind=c_char), intent(out) :: msg(*)
            integer(c_size_t), value :: cap
        end subroutine c_strerror
    end interface

    integer, parameter :: path_cap = 4352

contains

    !> Read the whole file path into text. msg is empty when it is done, else
    !> the reason. A regular file is read into a buffer of its size; a pipe,
    !> a FIFO or /dev/stdin, whose size is known only at its end, is read
    !> until end of file into a buffer that doubles as it fills. Memory that
    !> cannot be had is a message, not a crash.
    subroutine read_whole(path, text, msg)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: text
        character(len=:), allocatable, intent(out) :: msg
        character(len=:), allocatable :: bigger
        integer(c_int) :: rc, fd
        integer(c_long_long) :: size, n, got, cap
        integer :: st
        msg = ''
        rc = c_open_read(path // c_null_char, fd, size)
        if (rc /= 0) then
            text = ''
            msg = "cannot open: " // os_message(rc)
            return
        end if
        cap = size
        if (size < 0) cap = 65536
        allocate(character(len=cap) :: text, stat=st)
        if (st /= 0) then
            call c_close_read(fd)
            text = ''
            msg = 'cannot read: not enough memory for ' // int_text(cap) // ' bytes'
            return
        end if
        got = 0
        do
            n = 0
            if (got < cap) n = c_read(fd, text(got + 1:), int(cap - got, c_size_t))
            if (n < 0) then
                call c_close_read(fd)
                text = ''
                msg = "cannot read: " // os_message(int(-n, c_int))
                return
            end if
            got = got + n
            if (got < cap .or. size >= 0) exit
            ! the buffer is full and the size was not known: double it
            allocate(character(len=2 * cap) :: bigger, stat=st)
            if (st /= 0) then
                call c_close_read(fd)
                text = ''
                msg = 'cannot read: not enough memory for ' // int_text(2 * cap) // ' bytes'
                return
            end if
            bigger(1:cap) = text
            call move_alloc(bigger, text)
            cap = 2 * cap
        end do
        call c_close_read(fd)
        if (got < cap) text = text(1:got)
    end subroutine read_whole

    function int_text(v) result(s)
        integer(c_long_long), intent(in) :: v
        character(len=:), allocatable :: s
        character(len=24) :: buf
        write(buf, '(i0)') v
        s = trim(buf)
    end function int_text

    !> Write data as the whole file path. msg is empty when it is done, else
    !> the reason (the file is then as it was before).
    subroutine write_whole(path, data, msg)
        character(len=*), intent(in) :: path, data
        character(len=:), allocatable, intent(out) :: msg
        character(len=:), allocatable :: tmp, why
        integer :: fd
        call open_out(path, fd, tmp, msg)
        if (len(msg) > 0) return
        call write_out(fd, data, msg)
        if (len(msg) > 0) then
            call close_out(fd, tmp, -1_c_long_long, why)      ! abandoned: removed
            return
        end if
        call close_out(fd, tmp, int(len(data), c_long_long), msg)
        if (len(msg) == 0) call commit_file(tmp, path, msg)
    end subroutine write_whole

    !> Open a file to be written a piece at a time (write_out), whole or not
    !> at all: a fresh temporary file beside path (tmp, its name) or, for a
    !> device or FIFO target, the target itself (tmp empty). close_out ends
    !> it; commit_file then renames it into place.
    subroutine open_out(path, fd, tmp, msg)
        character(len=*), intent(in) :: path
        integer, intent(out) :: fd
        character(len=:), allocatable, intent(out) :: tmp, msg
        character(len=path_cap) :: buf
        integer(c_int) :: cfd
        buf = ''
        msg = os_message(c_open_out(path // c_null_char, cfd, buf, int(path_cap, c_size_t)))
        fd = int(cfd)
        tmp = c_string(buf)
    end subroutine open_out

    !> Append data to a file of open_out (or to standard output, fd 1).
    subroutine write_out(fd, data, msg)
        integer, intent(in) :: fd
        character(len=*), intent(in) :: data
        character(len=:), allocatable, intent(out) :: msg
        if (len(data) == 0) then
            msg = ''
            return
        end if
        msg = os_message(c_write(int(fd, c_int), data, int(len(data), c_size_t)))
    end subroutine write_out

    !> Start writing out a file of open_out without waiting (a hint; close_out
    !> fsyncs it): files whose writes are all started before the first of them
    !> is closed are then fsynced in about half the time.
    subroutine write_back(fd)
        integer, intent(in) :: fd
        call c_write_back(int(fd, c_int))
    end subroutine write_back

    !> Close a file of open_out that should hold total bytes: fsynced and its
    !> size checked when it is a temporary file, which is removed on failure.
    subroutine close_out(fd, tmp, total, msg)
        integer, intent(in) :: fd
        character(len=*), intent(in) :: tmp
        integer(c_long_long), intent(in) :: total
        character(len=:), allocatable, intent(out) :: msg
        msg = os_message(c_close_out(int(fd, c_int), tmp // c_null_char, total))
    end subroutine close_out

    !> Rename a staged file over its target (the target's directory fsynced,
    !> unless sync_dir is false: then the caller calls sync_dir_of after its
    !> last rename into that directory); nothing to do when it was written
    !> straight into a device (tmp empty).
    subroutine commit_file(tmp, path, msg, sync_dir)
        character(len=*), intent(in) :: tmp, path
        character(len=:), allocatable, intent(out) :: msg
        logical, intent(in), optional :: sync_dir
        integer(c_int) :: flag
        flag = 1
        if (present(sync_dir)) then
            if (.not. sync_dir) flag = 0
        end if
        msg = os_message(c_commit(tmp // c_null_char, path // c_null_char, flag))
    end subroutine commit_file

    !> fsync the directory that holds path (after renames into it).
    subroutine sync_dir_of(path)
        character(len=*), intent(in) :: path
        call c_sync_dir(path // c_null_char)
    end subroutine sync_dir_of

    !> Remove a staged file that is not to be committed.
    subroutine discard_file(tmp)
        character(len=*), intent(in) :: tmp
        if (len(tmp) > 0) call c_discard(tmp // c_null_char)
    end subroutine discard_file

    !> Take the lock of directory dir, waiting while another run holds it.
    subroutine lock_dir(dir, fd, msg)
        character(len=*), intent(in) :: dir
        integer, intent(out) :: fd
        character(len=:), allocatable, intent(out) :: msg
        integer(c_int) :: cfd
        msg = os_message(c_lock(dir // c_null_char, cfd))
        fd = int(cfd)
    end subroutine lock_dir

    subroutine unlock_dir(fd)
        integer, intent(in) :: fd
        call c_unlock(int(fd, c_int))
    end subroutine unlock_dir

    !> True when a and b name one existing file (a link or another spelling
    !> of the same path included).
    logical function same_file(a, b)
        character(len=*), intent(in) :: a, b
        same_file = c_same_file(a // c_null_char, b // c_null_char) == 1
    end function same_file

    !> The C library's text for an errno value; empty for 0.
    function os_message(rc) result(msg)
        integer(c_int), intent(in) :: rc
        character(len=:), allocatable :: msg
        character(len=256) :: buf
        if (rc == 0) then
            msg = ''
            return
        end if
        buf = ''
        call c_strerror(rc, buf, int(len(buf), c_size_t))
        msg = c_string(buf)
        if (len(msg) == 0) msg = 'error'
    end function os_message

    !> The text of a NUL-terminated C string held in a Fortran buffer.
    function c_string(buf) result(s)
        character(len=*), intent(in) :: buf
        character(len=:), allocatable :: s
        integer :: k
        k = index(buf, c_null_char)
        if (k == 0) then
            s = trim(buf)
        else
            s = buf(1:k - 1)
        end if
    end function c_string

end module base_files
