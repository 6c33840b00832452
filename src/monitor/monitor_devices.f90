!> The devices of the Dubna monitor, as the modern shell provides them to the
!> FORTRAN 77 programs in legacy/: the card reader (a deck file or standard
!> input), the line printer (the package's .lst listing), the three tape punches
!> (.ptp images with their .txt frame text), the job sheet (.job) and the
!> operator's console (standard error).
!>
!> A package's output is held in memory until the package is closed; then it is
!> staged in fresh temporary files (written in full, fsynced) and renamed into
!> place under the directory's lock, the job sheet last with the size and
!> SHA-256 of every other file; a failed package never leaves a partial tape
!> and never touches the good tapes of an earlier run.
!>
!> The deck is read byte for byte, whatever kind of file it is (a regular
!> file, a pipe, a FIFO, standard input), so every way in reads the same cards.
module monitor_devices
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, int64
    use, intrinsic :: iso_c_binding, only: c_long_long
    use base_error, only: no_memory
    use base_os, only: make_dirs, is_dir, read_fd
    use base_files, only: open_out, write_out, write_back, close_out, commit_file, &
                          sync_dir_of, discard_file, lock_dir, unlock_dir, same_file
    use base_io, only: say
    use base_sha256, only: sha256_hex
    implicit none
    private

    public :: dev_load_deck, dev_load_stdin, dev_set_output, dev_next_card
    public :: dev_print, dev_error, dev_open, dev_punch, dev_text, dev_job, dev_close
    public :: dev_io_failed

    !> A growing byte string.
    type :: byte_buffer
        character(len=:), allocatable :: data
        integer :: n = 0
    contains
        procedure :: append => buffer_append
        procedure :: put => buffer_put
        procedure :: line => buffer_line
        procedure :: clear => buffer_clear
    end type byte_buffer

    character(len=*), parameter :: nl = achar(10)
    character(len=*), parameter :: tape_suffix(3) = [character(len=6) :: 'small', 'large', 'cond']
    !> The largest deck read, in bytes (1 GiB).
    integer, parameter :: max_deck = 1073741824

    character(len=:), allocatable :: deck, deck_label, deck_path, out_dir, pkg_name
    integer :: deck_pos = 1
    logical :: io_failed = .false.
    type(byte_buffer) :: tape(3), text(3), job, listing

contains

    subroutine buffer_append(self, s)
        class(byte_buffer), intent(inout) :: self
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: tmp
        integer :: need, st
        need = self%n + len(s)
        if (.not. allocated(self%data)) then
            allocate(character(len=max(4096, need)) :: self%data, stat=st)
            if (st /= 0) call no_memory('the output', int(need, int64))
        end if
        if (need > len(self%data)) then
            allocate(character(len=max(2 * len(self%data), need)) :: tmp, stat=st)
            if (st /= 0) call no_memory('the output', 2 * int(len(self%data), int64))
            tmp(1:self%n) = self%data(1:self%n)
            call move_alloc(tmp, self%data)
        end if
        self%data(self%n + 1:need) = s
        self%n = need
    end subroutine buffer_append

    !> One character (a tape row): the same as append, without the call of
    !> memmove for a single byte that append costs (millions of rows a board).
    subroutine buffer_put(self, c)
        class(byte_buffer), intent(inout) :: self
        character, intent(in) :: c
        if (allocated(self%data)) then
            if (self%n < len(self%data)) then
                self%n = self%n + 1
                self%data(self%n:self%n) = c
                return
            end if
        end if
        call self%append(c)
    end subroutine buffer_put

    !> A line of text without its trailing blanks, then a newline; without the
    !> temporary that trim(line) // nl would allocate.
    subroutine buffer_line(self, line)
        class(byte_buffer), intent(inout) :: self
        character(len=*), intent(in) :: line
        call self%append(line(1:len_trim(line)))
        call self%put(nl)
    end subroutine buffer_line

    subroutine buffer_clear(self)
        class(byte_buffer), intent(inout) :: self
        self%n = 0
    end subroutine buffer_clear

    !> Read a whole deck file. ok is false (and msg says why) when it cannot be read.
    subroutine dev_load_deck(path, ok, msg)
        character(len=*), intent(in) :: path
        logical, intent(out) :: ok
        character(len=:), allocatable, intent(out) :: msg
        integer :: u, ios, istat
        integer(int64) :: size
        character(len=256) :: iomsg
        ok = .false.
        deck_label = path
        deck_path = path
        open(newunit=u, file=path, access='stream', form='unformatted', action='read', &
             status='old', iostat=ios, iomsg=iomsg)
        if (ios /= 0) then
            msg = 'cannot open the deck: ' // trim(iomsg)
            return
        end if
        ! a file known to be too large is refused unread (a pipe's size is not
        ! known: read_fd stops one byte past the limit)
        inquire(unit=u, size=size)
        if (size > max_deck) then
            istat = 2
        else
            call read_fd(fnum(u), max_deck, deck, istat)
        end if
        close(u)
        call load_status(istat, ok, msg)
    end subroutine dev_load_deck

    !> Read the whole deck from standard input (ok and msg as for dev_load_deck).
    subroutine dev_load_stdin(ok, msg)
        logical, intent(out) :: ok
        character(len=:), allocatable, intent(out) :: msg
        integer :: istat
        deck_label = '<stdin>'
        call read_fd(0, max_deck, deck, istat)
        call load_status(istat, ok, msg)
    end subroutine dev_load_stdin

    subroutine load_status(istat, ok, msg)
        integer, intent(in) :: istat
        logical, intent(out) :: ok
        character(len=:), allocatable, intent(out) :: msg
        character(len=12) :: nmax
        ok = istat == 0
        msg = ''
        deck_pos = 1
        if (istat == 1) msg = 'cannot read the deck (a directory?)'
        if (istat == 2) then
            write(nmax, '(i0)') max_deck
            msg = 'the deck has more than ' // trim(nmax) // ' bytes; split the job'
        end if
        if (.not. ok) deck = ''
    end subroutine load_status

    !> Choose (and create) the output directory.
    subroutine dev_set_output(dir, ok, msg)
        character(len=*), intent(in) :: dir
        logical, intent(out) :: ok
        character(len=:), allocatable, intent(out) :: msg   !< why not, when not ok
        logical :: there
        integer :: i, start
        out_dir = dir
        call make_dirs(dir, ok)
        if (ok) return
        inquire(file=dir, exist=there)
        if (there) then
            msg = 'a file of that name is in the way; -o names a directory'
            return
        end if
        msg = 'it could not be made (is its parent writable?)'
        ! a component longer than a file name may be (ENAMETOOLONG)
        start = 1
        do i = 1, len(dir) + 1
            if (i <= len(dir)) then
                if (dir(i:i) /= '/') cycle
            end if
            if (i - start > 255) then
                msg = 'a name in it is longer than the 255 characters a file name may have'
                return
            end if
            start = i + 1
        end do
    end subroutine dev_set_output

    !> The card reader: the next line of the deck, its first 80 columns in card
    !> and its full length in ncol; a CR before the LF is dropped. iend = 1 at the end.
    subroutine dev_next_card(card, ncol, iend)
        character(len=80), intent(out) :: card
        integer, intent(out) :: ncol, iend
        integer :: eol, last
        card = ' '
        ncol = 0
        if (deck_pos > len(deck)) then
            iend = 1
            return
        end if
        iend = 0
        eol = index(deck(deck_pos:), nl)
        if (eol == 0) then
            last = len(deck)
            eol = len(deck) + 1
        else
            eol = deck_pos + eol - 1
            last = eol - 1
        end if
        if (last >= deck_pos) then
            if (deck(last:last) == achar(13)) last = last - 1
        end if
        ncol = max(0, last - deck_pos + 1)
        if (ncol > 0) card = deck(deck_pos:deck_pos + min(ncol, 80) - 1)
        deck_pos = eol + 1
    end subroutine dev_next_card

    !> The line printer: one line of the current package's listing.
    subroutine dev_print(line)
        character(len=*), intent(in) :: line
        call listing%line(line)
    end subroutine dev_print

    !> The operator's console: one message, prefixed with the deck's name.
    subroutine dev_error(line)
        character(len=*), intent(in) :: line
        write(error_unit, '(a)') deck_label // ': ' // trim(line)
    end subroutine dev_error

    !> Start the output of a package; name is already sanitised by TENZOR.
    subroutine dev_open(name)
        character(len=*), intent(in) :: name
        integer :: i
        pkg_name = trim(name)
        do i = 1, 3
            call tape(i)%clear()
            call text(i)%clear()
        end do
        call job%clear()
        call listing%clear()
    end subroutine dev_open

    !> A tape punch: one row (0..31) on tape unit iu.
    subroutine dev_punch(iu, row)
        integer, intent(in) :: iu, row
        call tape(iu)%put(achar(iand(row, 31)))
    end subroutine dev_punch

    subroutine dev_text(iu, line)
        integer, intent(in) :: iu
        character(len=*), intent(in) :: line
        call text(iu)%line(line)
    end subroutine dev_text

    subroutine dev_job(line)
        character(len=*), intent(in) :: line
        call job%line(line)
    end subroutine dev_job

    !> Close the package: the listing always, the tapes, texts and job sheet only
    !> when keep is true. The job sheet comes last and records the size and the
    !> SHA-256 of every other file of the package, so that a tool can tell a
    !> package whose files do not belong together. Every file is first staged
    !> (base_files: a fresh temporary file, written in full, its write-out to
    !> disk started), then each is fsynced and its size checked: so started
    !> together, the eight fsyncs take about half as long as one after
    !> another (docs/FILES.md). Only when all are staged and
    !> fsynced, and none of the final names is a directory or the deck itself,
    !> are they renamed into place, under the output directory's
    !> lock, so that two runs into one directory never mix their files. When
    !> anything fails, no file of the package is changed, and the console says so.
    subroutine dev_close(keep)
        logical, intent(in) :: keep
        character(len=:), allocatable :: base, msg, why
        type(byte_buffer) :: sheet
        character(len=4096) :: final(8), staged(8)
        integer :: nfiles, i, j, lockfd, fds(8)
        integer(c_long_long) :: sizes(8)
        logical :: ok
        base = out_dir // '/' // pkg_name
        nfiles = 0
        ok = .true.
        call add(base // '.lst')
        if (keep) then
            do i = 1, 3
                call add(base // '-' // trim(tape_suffix(i)) // '.ptp')
                call add(base // '-' // trim(tape_suffix(i)) // '.txt')
            end do
            call add(base // '.job')
        end if
        do i = 1, nfiles
            if (.not. ok) exit
            if (is_dir(trim(final(i)))) then
                call say('tenzor: cannot write ' // trim(final(i)) // ': a directory has that name')
                ok = .false.
            else if (allocated(deck_path)) then
                if (same_file(deck_path, trim(final(i)))) then
                    call say('tenzor: cannot write ' // trim(final(i)) // ': it is the deck ' // &
                             'being read; choose another output directory (-o)')
                    ok = .false.
                end if
            end if
        end do
        staged = ''
        fds = -1
        if (ok) then
            call stage(1, listing)
            if (keep) then
                do i = 1, 3
                    call stage(2 * i, tape(i))
                    call stage(2 * i + 1, text(i))
                end do
                ! the job sheet: TENZOR's lines, then the package's files
                sheet = job
                call sheet%line('listing = ' // pkg_name // '.lst')
                call sheet%line('listing.bytes = ' // itoa(listing%n))
                call sheet%line('listing.sha256 = ' // sha256_hex(bytes_of(listing)))
                do i = 1, 3
                    call sheet%line(trim(tape_suffix(i)) // '.bytes = ' // itoa(tape(i)%n))
                    call sheet%line(trim(tape_suffix(i)) // '.sha256 = ' // &
                                    sha256_hex(bytes_of(tape(i))))
                    call sheet%line(trim(tape_suffix(i)) // '.text_bytes = ' // itoa(text(i)%n))
                    call sheet%line(trim(tape_suffix(i)) // '.text_sha256 = ' // &
                                    sha256_hex(bytes_of(text(i))))
                end do
                call stage(8, sheet)
            end if
        end if
        ! every staged file fsynced, its size checked and closed (after a
        ! failure too: they are removed below)
        do i = 1, nfiles
            if (fds(i) < 0) cycle
            call close_out(fds(i), trim(staged(i)), sizes(i), why)
            fds(i) = -1
            if (len(why) > 0 .and. ok) then
                call say('tenzor: cannot write ' // trim(final(i)) // ': ' // why)
                ok = .false.
            end if
        end do
        if (.not. ok) then
            do i = 1, nfiles
                call discard_file(trim(staged(i)))
            end do
            io_failed = .true.
            call say('tenzor: ' // pkg_name // ': no file written; ' // &
                     'earlier files of this name are left as they were')
            write(output_unit, '(a)') pkg_name // ': cannot write its files; earlier ' // &
                'files of this name are left as they were'
            return
        end if
        call lock_dir(out_dir, lockfd, msg)
        if (len(msg) > 0) then
            call say('tenzor: cannot lock ' // out_dir // ' (' // msg // '); writing ' // &
                     'without the lock')
            lockfd = -1
        end if
        ! the files of a package are renamed into one directory, which is
        ! fsynced once after the last of them (a failed rename fsyncs it too)
        do i = 1, nfiles
            call commit_file(trim(staged(i)), trim(final(i)), msg, sync_dir=.false.)
            if (len(msg) > 0) then
                call say('tenzor: cannot rename into ' // trim(final(i)) // ' (' // msg // &
                         '); ' // pkg_name // ': the files before it in the list are new, ' // &
                         'the others are left as they were')
                do j = i + 1, nfiles
                    call discard_file(trim(staged(j)))
                end do
                if (i > 1) call sync_dir_of(trim(final(1)))
                call unlock_dir(lockfd)
                io_failed = .true.
                write(output_unit, '(a)') pkg_name // ': cannot write all its files'
                return
            end if
        end do
        call sync_dir_of(trim(final(1)))
        call unlock_dir(lockfd)
        if (keep) then
            write(output_unit, '(a)') pkg_name // ': tapes ' // base // '-small.ptp ' // &
                base // '-large.ptp ' // base // '-cond.ptp, listing ' // base // '.lst'
        else
            write(output_unit, '(a)') pkg_name // ': errors, no tapes punched; see ' // &
                base // '.lst'
        end if
    contains
        subroutine add(path)
            character(len=*), intent(in) :: path
            nfiles = nfiles + 1
            final(nfiles) = path
        end subroutine add

        !> File k written in full to a fresh temporary file, left open (fds)
        !> for the fsync that follows the last.
        subroutine stage(k, buf)
            integer, intent(in) :: k
            type(byte_buffer), intent(in) :: buf
            character(len=:), allocatable :: tmp, why
            integer :: fd
            if (.not. ok) return
            call open_out(trim(final(k)), fd, tmp, why)
            if (len(why) == 0) then
                staged(k) = tmp
                fds(k) = fd
                sizes(k) = int(buf%n, c_long_long)
                if (buf%n > 0) call write_out(fd, buf%data(1:buf%n), why)
            end if
            if (len(why) > 0) then
                call say('tenzor: cannot write ' // trim(final(k)) // ': ' // why)
                ok = .false.
            else
                call write_back(fd)
            end if
        end subroutine stage
    end subroutine dev_close

    !> The bytes a buffer holds.
    function bytes_of(buf) result(b)
        type(byte_buffer), intent(in) :: buf
        character(len=:), allocatable :: b
        if (buf%n > 0) then
            b = buf%data(1:buf%n)
        else
            b = ''
        end if
    end function bytes_of

    !> An integer as decimal text.
    function itoa(n) result(s)
        integer, intent(in) :: n
        character(len=:), allocatable :: s
        character(len=12) :: buf
        write(buf, '(i0)') n
        s = trim(buf)
    end function itoa

    logical function dev_io_failed()
        dev_io_failed = io_failed
    end function dev_io_failed

end module monitor_devices
