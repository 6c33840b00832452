!> The devices of the Dubna monitor, as the modern shell provides them to the
!> FORTRAN 77 programs in legacy/: the card reader (a deck file or standard
!> input), the line printer (the package's .lst listing), the three tape punches
!> (.ptp images with their .txt frame text), the job sheet (.job) and the
!> operator's console (standard error).
!>
!> A package's output is held in memory until the package is closed; then it is
!> written to temporary files and renamed into place, so a failed package never
!> leaves a partial tape and never touches the good tapes of an earlier run.
!> A write counts as done only when the file on disk has every byte (the
!> Fortran run-time library does not report every failed write, e.g. a full
!> disk).
!>
!> The deck is read byte for byte, whatever kind of file it is (a regular
!> file, a pipe, a FIFO, standard input), so every way in reads the same cards.
module monitor_devices
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
    use base_os, only: make_dirs, rename_file, remove_file, is_dir, read_fd
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

    character(len=:), allocatable :: deck, deck_label, out_dir, pkg_name
    integer :: deck_pos = 1
    logical :: io_failed = .false.
    type(byte_buffer) :: tape(3), text(3), job, listing

contains

    subroutine buffer_append(self, s)
        class(byte_buffer), intent(inout) :: self
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: tmp
        integer :: need
        need = self%n + len(s)
        if (.not. allocated(self%data)) allocate(character(len=max(4096, need)) :: self%data)
        if (need > len(self%data)) then
            allocate(character(len=max(2 * len(self%data), need)) :: tmp)
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
        character(len=256) :: iomsg
        ok = .false.
        deck_label = path
        open(newunit=u, file=path, access='stream', form='unformatted', action='read', &
             status='old', iostat=ios, iomsg=iomsg)
        if (ios /= 0) then
            msg = 'cannot open the deck: ' // trim(iomsg)
            return
        end if
        call read_fd(fnum(u), max_deck, deck, istat)
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
    subroutine dev_set_output(dir, ok)
        character(len=*), intent(in) :: dir
        logical, intent(out) :: ok
        out_dir = dir
        call make_dirs(dir, ok)
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
    !> when keep is true. Every file is written under a temporary name first; the
    !> renames happen only when all of them were written in full and none of the
    !> final names is a directory. When a write fails, no file of the package is
    !> changed, and the console says so.
    subroutine dev_close(keep)
        logical, intent(in) :: keep
        character(len=:), allocatable :: base
        character(len=4096) :: final(8)
        integer :: nfiles, i, j
        logical :: ok
        base = out_dir // '/' // pkg_name
        nfiles = 0
        ok = .true.
        call stage(base // '.lst', listing, ok)
        if (keep) then
            do i = 1, 3
                call stage(base // '-' // trim(tape_suffix(i)) // '.ptp', tape(i), ok)
                call stage(base // '-' // trim(tape_suffix(i)) // '.txt', text(i), ok)
            end do
            call stage(base // '.job', job, ok)
        end if
        do i = 1, nfiles
            if (ok .and. is_dir(trim(final(i)))) then
                write(error_unit, '(a)') 'tenzor: cannot write ' // trim(final(i)) // &
                    ': a directory has that name'
                ok = .false.
            end if
        end do
        if (.not. ok) then
            do i = 1, nfiles
                call remove_file(temp_name(trim(final(i))))
            end do
            io_failed = .true.
            write(error_unit, '(a)') 'tenzor: ' // pkg_name // ': no file written; ' // &
                'earlier files of this name are left as they were'
            write(output_unit, '(a)') pkg_name // ': cannot write its files; earlier ' // &
                'files of this name are left as they were'
            return
        end if
        do i = 1, nfiles
            call rename_file(temp_name(trim(final(i))), trim(final(i)), ok)
            if (.not. ok) then
                write(error_unit, '(a)') 'tenzor: cannot rename into ' // trim(final(i)) // &
                    '; ' // pkg_name // ': the files before it in the list are new, ' // &
                    'the others are left as they were'
                do j = i, nfiles
                    call remove_file(temp_name(trim(final(j))))
                end do
                io_failed = .true.
                write(output_unit, '(a)') pkg_name // ': cannot write all its files'
                return
            end if
        end do
        if (keep) then
            write(output_unit, '(a)') pkg_name // ': tapes ' // base // '-small.ptp ' // &
                base // '-large.ptp ' // base // '-cond.ptp, listing ' // base // '.lst'
        else
            write(output_unit, '(a)') pkg_name // ': errors, no tapes punched; see ' // &
                base // '.lst'
        end if
    contains
        subroutine stage(path, buf, ok)
            character(len=*), intent(in) :: path
            type(byte_buffer), intent(in) :: buf
            logical, intent(inout) :: ok
            integer :: u, ios, ios2, nbytes
            character(len=256) :: iomsg
            if (.not. ok) return
            nfiles = nfiles + 1
            final(nfiles) = path
            iomsg = ''
            open(newunit=u, file=temp_name(path), access='stream', form='unformatted', &
                 status='replace', action='write', iostat=ios, iomsg=iomsg)
            if (ios == 0) then
                if (buf%n > 0) write(u, iostat=ios, iomsg=iomsg) buf%data(1:buf%n)
                close(u, iostat=ios2)
                if (ios == 0) ios = ios2
                if (ios == 0) then
                    inquire(file=temp_name(path), size=nbytes)
                    if (nbytes /= buf%n) then
                        ios = -1
                        iomsg = 'the file on disk is short (is the disk full?)'
                    end if
                end if
            end if
            if (ios /= 0) then
                write(error_unit, '(a)') 'tenzor: cannot write ' // path // ': ' // trim(iomsg)
                ok = .false.
            end if
        end subroutine stage
    end subroutine dev_close

    !> The temporary name of an output file: a dot file beside it.
    function temp_name(path) result(tmp)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: tmp
        integer :: slash
        slash = index(path, '/', back=.true.)
        tmp = path(1:slash) // '.' // path(slash + 1:) // '.tmp'
    end function temp_name

    logical function dev_io_failed()
        dev_io_failed = io_failed
    end function dev_io_failed

end module monitor_devices
