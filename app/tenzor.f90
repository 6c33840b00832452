!> tenzor: the modern shell around the 1977 program TENZOR (legacy/tenzor.f).
!> It does what the Dubna monitor did for the program: finds the deck, sets up
!> the card reader, the printer and the punches (src/monitor/), calls
!> the FORTRAN 77 entry point and turns its verdict into an exit status:
!> 0 all packages punched, 1 the deck had errors, 2 usage or I/O trouble (or a
!> broken build: TENZOR found its code table unset).
program tenzor_shell
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
    use base_args, only: get_arg
    use base_version, only: VERSION, VERSION_LINE_TAIL
    use monitor_devices, only: dev_load_deck, dev_load_stdin, dev_set_output, dev_io_failed
    implicit none

    interface
        subroutine tenzor(icodea, lstrca, irc)
            integer, intent(in) :: icodea, lstrca
            integer, intent(out) :: irc
        end subroutine tenzor
    end interface

    character(len=:), allocatable :: deck_path, out_dir, msg, arg
    integer :: icode, istrict, irc, i, nargs
    logical :: ok

    deck_path = ''
    out_dir = 'out'
    icode = 0
    istrict = 0
    nargs = command_argument_count()
    i = 1
    do while (i <= nargs)
        arg = get_arg(i)
        select case (arg)
        case ('-h', '--help')
            call usage(output_unit)
            stop 0, quiet=.true.
        case ('--version')
            write(output_unit, '(a)') 'tenzor ' // VERSION // VERSION_LINE_TAIL
            stop 0, quiet=.true.
        case ('-o', '--output')
            if (i == nargs) call fail('option ' // arg // ' needs a directory')
            i = i + 1
            out_dir = get_arg(i)
            if (len(out_dir) == 0) call fail('option -o needs a directory, not an empty string')
        case ('--strict')
            istrict = 1
        case ('--code')
            if (i == nargs) call fail('option --code needs 8 or K')
            i = i + 1
            select case (get_arg(i))
            case ('8')
                icode = 1
            case ('K', 'k')
                icode = 2
            case default
                call fail('--code takes 8 (the "8" code) or K (with control), not "' // &
                          get_arg(i) // '"')
            end select
        case default
            if (len(arg) > 1 .and. arg(1:1) == '-') call fail('unknown option ' // arg)
            if (len(arg) == 0) call fail('an empty argument is not a deck')
            if (len(deck_path) > 0) call fail('one deck at a time: ' // deck_path // ' and ' // arg)
            deck_path = arg
        end select
        i = i + 1
    end do

    if (len(deck_path) > 0) then
        call dev_load_deck(deck_path, ok, msg)
        if (.not. ok) call fail_io(deck_path // ': ' // msg)
    else
        call dev_load_stdin(ok, msg)
        if (.not. ok) call fail_io('standard input: ' // msg)
    end if
    call dev_set_output(out_dir, ok, msg)
    if (.not. ok) call fail_io('cannot create the output directory ' // out_dir // ': ' // msg)

    call tenzor(icode, istrict, irc)

    if (dev_io_failed() .or. irc == 2) stop 2, quiet=.true.
    if (irc /= 0) stop 1, quiet=.true.

contains

    subroutine usage(unit)
        integer, intent(in) :: unit
        write(unit, '(a)') 'usage: tenzor [DECK] [-o DIR] [--code 8|K] [--strict]', &
            '', &
            'Reads a card deck (DECK, or standard input) and punches, for each package,', &
            'the three EM-703 tapes NAME-small.ptp, NAME-large.ptp, NAME-cond.ptp with', &
            'their frame text (.txt), the listing NAME.lst and the job sheet NAME.job.', &
            '', &
            '  -o DIR      output directory (default: out; created if missing)', &
            '  --code 8|K  tape code: 8 plain, K with control; overrides the P card', &
            '  --strict    warnings are errors: data in columns a card does not read', &
            '              stops its package (no tapes), as any error does', &
            '  -h, --help  this text', &
            '  --version   the version', &
            '', &
            'Exit status: 0 all packages punched, 1 the deck has errors (see the', &
            'listings and standard error), 2 usage or I/O error.'
    end subroutine usage

    subroutine fail(text)
        character(len=*), intent(in) :: text
        write(error_unit, '(a)') 'tenzor: ' // text
        write(error_unit, '(a)') 'usage: tenzor [DECK] [-o DIR] [--code 8|K] [--strict]  (tenzor --help)'
        stop 2, quiet=.true.
    end subroutine fail

    !> A file that cannot be read or made: its one line, without the usage
    !> line (the command line was right).
    subroutine fail_io(text)
        character(len=*), intent(in) :: text
        write(error_unit, '(a)') 'tenzor: ' // text
        stop 2, quiet=.true.
    end subroutine fail_io

end program tenzor_shell
