!> The command line of em703: one parser for every subcommand, the help
!> texts, and the usage errors. parse_command_line reads the arguments into a
!> cli_t (or prints the help and stops with status 0, or names the mistake on
!> standard error and stops with status 2); app/em703.f90 then hands the
!> cli_t to the subcommand's function in em703_commands.
!>
!> Every subcommand reads its arguments the same way, left to right: -h or
!> --help prints its help; an option it takes (OPTIONS below) reads its value
!> from the next argument; anything else is its one file (for split: DX or
!> DY, which may be negative). Each option may be given once (-o and
!> --output are one option); a value is never taken from an argument that
!> is itself an option (--...). The letters of a --code value are read in
!> either case. The limits of the values are the library's own: the field
!> of em703_sim, the largest number of em703_codec.
module em703_cli
    use, intrinsic :: iso_fortran_env, only: int64, real64, output_unit
    use base_args, only: get_arg
    use base_io, only: say
    use base_version, only: VERSION, VERSION_LINE_TAIL
    use base_text, only: str, lower, parse_int, parse_mm, parse_real
    use em703_codec, only: MAX_NUMBER
    use em703_jobsheet, only: parse_scale, machine_scale
    use em703_sim, only: FIELD_UNITS
    implicit none
    private
    public :: cli_t, parse_command_line

    !> What the command line asks for. Unused fields keep their defaults,
    !> which are the subcommands' defaults.
    type, public :: cli_t
        character(len=:), allocatable :: command    !< list, sim, svg, gcode, gerber, drill, punch, view, split, html, check
        character(len=:), allocatable :: file       !< the one file argument
        character(len=:), allocatable :: out        !< -o FILE ('' = the default)
        !> --code: a tape code (list, sim: 8, K or auto; view: auto, em703, iso or
        !> eia) or a punch code (iso or eia; '' = not given)
        character(len=:), allocatable :: code
        character(len=:), allocatable :: svg        !< sim --svg FILE ('' = none)
        logical :: utf8 = .false.                   !< list --utf8
        logical :: bare = .false.                   !< list --bare
        logical :: use_z = .false.                  !< gcode --z
        character(len=:), allocatable :: dialect    !< gcode --dialect linuxcnc|grbl|iso-1970s
        !> gcode (iso-1970s) and check --frame address|fixed|variable ('' = not given)
        character(len=:), allocatable :: frame
        integer :: num = 1, den = 1                 !< sim --scale N:D
        integer(int64) :: start_x = 0, start_y = 0  !< sim --start, 0.01 mm
        integer(int64) :: tool = 50                 !< sim --tool, 0.01 mm
        real(real64) :: chord_tol = 0               !< gcode --chords, mm (0: arcs stay arcs)
        integer :: first = 1, last = huge(1)        !< view --rows FIRST:LAST
        integer(int64) :: max_pulses = 9999         !< split --max
        logical :: equal = .false.                  !< split --equal
        integer(int64) :: move(2) = 0               !< split DX DY, pulses
    end type cli_t

    !> The widest tool sim --svg draws, 0.01 mm (20 mm).
    integer(int64), parameter :: MAX_TOOL = 2000

    !> The options of each subcommand, besides -h and --help.
    character(len=*), parameter :: SUBCOMMANDS(11) = [character(len=6) :: &
        'list', 'sim', 'svg', 'gcode', 'gerber', 'drill', 'punch', 'view', 'split', 'html', 'check']
    character(len=*), parameter :: OPTIONS(11) = [character(len=48) :: &
        '--utf8 --bare --code', &
        '--scale --start --svg --tool --code', &
        '-o --output', &
        '-o --output --z --chords --dialect --frame', &
        '-o --output', &
        '-o --output', &
        '-o --output --code', &
        '--code --rows', &
        '--max --equal', &
        '-o --output', &
        '--frame']

contains

    !> Read the whole command line into cli; stops with status 0 after a
    !> help text and with status 2 after a usage error.
    subroutine parse_command_line(cli)
        type(cli_t), intent(out) :: cli
        character(len=:), allocatable :: arg, given
        integer :: nargs, i, k, nmove
        logical :: help_on

        nargs = command_argument_count()
        if (nargs == 0) call usage_error('', 'no subcommand')
        cli%command = get_arg(1)
        ! em703 help SUBCOMMAND: that subcommand's help, found as any subcommand is
        help_on = cli%command == 'help' .and. nargs >= 2
        if (help_on) then
            if (nargs > 2) call usage_error('', 'help takes one subcommand, not "' // &
                get_arg(3) // '" too')
            cli%command = get_arg(2)
        end if
        if (cli%command == '-h' .or. cli%command == '--help' .or. cli%command == 'help') then
            call help('')
            stop 0, quiet=.true.
        end if
        if (cli%command == '--version') then
            write(output_unit, '(a)') 'em703 ' // VERSION // VERSION_LINE_TAIL
            stop 0, quiet=.true.
        end if
        k = 0
        do i = 1, size(SUBCOMMANDS)
            if (SUBCOMMANDS(i) == cli%command) k = i
        end do
        if (k == 0) call usage_error('', 'unknown subcommand "' // cli%command // '"')
        if (help_on) then
            call help(cli%command)
            stop 0, quiet=.true.
        end if
        cli%file = ''
        cli%out = ''
        cli%svg = ''
        cli%code = 'auto'
        cli%dialect = 'linuxcnc'
        cli%frame = ''
        if (cli%command == 'punch') cli%code = ''
        nmove = 0
        given = ' '
        i = 2
        do while (i <= nargs)
            arg = get_arg(i)
            if (arg == '-h' .or. arg == '--help') then
                call help(cli%command)
                stop 0, quiet=.true.
            else if (takes(OPTIONS(k), arg)) then
                if (arg == '--output') arg = '-o'
                if (index(given, ' ' // arg // ' ') > 0) call usage_error(cli%command, &
                    'option ' // get_arg(i) // ' given twice: give it once')
                given = given // arg // ' '
                call take_option(cli, arg, i, nargs)
            else if (cli%command == 'split') then
                if (len(arg) > 1) then
                    if (arg(1:1) == '-' .and. verify(arg(2:2), '0123456789') /= 0) &
                        call usage_error('split', 'unknown option ' // arg)
                end if
                call take_move(cli, arg, nmove)
            else
                call take_file(cli%command, cli%file, arg)
            end if
            i = i + 1
        end do

        select case (cli%command)
        case ('list', 'sim', 'view')
            call need_file(cli%command, cli%file, 'TAPE')
        case ('check')
            call need_file('check', cli%file, 'PROGRAM (a text, or an ISO or EIA tape image)')
        case ('svg', 'gerber', 'drill', 'html')
            call need_file(cli%command, cli%file, 'JOB (a job sheet NAME.job)')
        case ('gcode')
            call need_file(cli%command, cli%file, 'TAPE or JOB')
            if (len(cli%frame) > 0 .and. cli%dialect /= 'iso-1970s') call usage_error('gcode', &
                '--frame is for --dialect iso-1970s (seed 004''s frames), not ' // cli%dialect)
            if (cli%use_z .and. cli%dialect == 'iso-1970s') call usage_error('gcode', &
                '--z is for linuxcnc and grbl: iso-1970s always moves the tool up and down in Z')
        case ('punch')
            if (len(cli%code) == 0) call usage_error('punch', 'missing --code iso|eia')
            call need_file('punch', cli%file, 'FILE (the text to punch)')
        case ('split')
            if (nmove /= 2) call usage_error('split', 'needs DX and DY, in pulses')
        end select
        if (len(cli%frame) == 0) cli%frame = 'address'
    end subroutine parse_command_line

    !> True if arg is one of the blank-separated options.
    logical function takes(options, arg)
        character(len=*), intent(in) :: options, arg
        takes = len(arg) > 0 .and. index(arg, ' ') == 0
        if (takes) takes = index(' ' // trim(options) // ' ', ' ' // arg // ' ') > 0
    end function takes

    !> An option of cli%command and, from the next argument, its value.
    subroutine take_option(cli, arg, i, nargs)
        type(cli_t), intent(inout) :: cli
        character(len=*), intent(in) :: arg
        integer, intent(inout) :: i
        integer, intent(in) :: nargs
        character(len=:), allocatable :: sub, v
        integer(int64) :: a, b
        integer :: p
        logical :: ok

        sub = cli%command
        select case (arg)
        case ('--utf8')
            cli%utf8 = .true.
        case ('--bare')
            cli%bare = .true.
        case ('--z')
            cli%use_z = .true.
        case ('--equal')
            cli%equal = .true.
        case ('--dialect')
            v = option_value(sub, i, nargs)
            select case (v)
            case ('linuxcnc', 'grbl', 'iso-1970s')
                cli%dialect = v
            case default
                call usage_error(sub, '--dialect takes linuxcnc, grbl or iso-1970s, not "' // v // '"')
            end select
        case ('--frame')
            v = option_value(sub, i, nargs)
            select case (v)
            case ('address', 'fixed', 'variable')
                cli%frame = v
            case default
                call usage_error(sub, '--frame takes address, fixed or variable, not "' // v // '"')
            end select
        case ('-o', '--output')
            cli%out = option_value(sub, i, nargs)
            if (len(cli%out) == 0) call usage_error(sub, get_arg(i - 1) // ' needs a file name, ' // &
                'not an empty one (without it the output goes to standard output)')
        case ('--code')
            v = option_value(sub, i, nargs)
            select case (sub)
            case ('punch')
                select case (lower(v))
                case ('iso', 'eia')
                    cli%code = lower(v)
                case default
                    call usage_error('punch', '--code takes iso or eia, not "' // v // '"')
                end select
            case ('view')
                select case (lower(v))
                case ('auto', 'em703', 'iso', 'eia')
                    cli%code = lower(v)
                case default
                    call usage_error('view', '--code takes auto, em703, iso or eia, not "' // v // '"')
                end select
            case default
                select case (lower(v))
                case ('8', 'auto')
                    cli%code = lower(v)
                case ('k')
                    cli%code = 'K'
                case default
                    call usage_error(sub, '--code takes 8, K or auto, not "' // v // '"')
                end select
            end select
        case ('--scale')
            v = option_value(sub, i, nargs)
            call parse_scale(v, cli%num, cli%den, ok)
            if (ok) ok = machine_scale(cli%num, cli%den)
            if (.not. ok) call usage_error(sub, '--scale takes one of the machine''s ' // &
                'scales 1:100 1:10 1:5 1:2 1:1 2:1 5:1 50:1 100:1, not "' // v // '"')
        case ('--start')
            v = option_value(sub, i, nargs)
            p = index(v, ',')
            ok = p > 0
            if (ok) call parse_mm(v(1:p - 1), cli%start_x, ok)
            if (ok) call parse_mm(v(p + 1:), cli%start_y, ok)
            if (ok) ok = cli%start_x >= 0 .and. cli%start_x <= FIELD_UNITS .and. &
                         cli%start_y >= 0 .and. cli%start_y <= FIELD_UNITS
            if (.not. ok) call usage_error(sub, '--start takes X,Y in mm on the field ' // &
                '(0 to ' // str(FIELD_UNITS / 100) // ', two decimals), not "' // v // '"')
        case ('--svg')
            cli%svg = option_value(sub, i, nargs)
            if (len(cli%svg) == 0) call usage_error(sub, '--svg needs a file name')
        case ('--tool')
            v = option_value(sub, i, nargs)
            call parse_mm(v, cli%tool, ok)
            if (.not. ok .or. cli%tool <= 0 .or. cli%tool > MAX_TOOL) call usage_error(sub, &
                '--tool takes the tool width in mm (0.01 to ' // str(MAX_TOOL / 100) // &
                '.00), not "' // v // '"')
        case ('--chords')
            v = option_value(sub, i, nargs)
            call parse_real(v, cli%chord_tol, ok)
            if (.not. ok .or. cli%chord_tol < 0.001_real64 .or. cli%chord_tol > 100) &
                call usage_error(sub, '--chords takes the tolerance in mm (0.001 to 100), not "' &
                                 // v // '"')
        case ('--rows')
            v = option_value(sub, i, nargs)
            p = index(v, ':')
            ok = p > 1 .and. p < len(v)
            if (ok) call parse_int(v(1:p - 1), a, ok)
            if (ok) call parse_int(v(p + 1:), b, ok)
            if (ok) ok = a >= 1 .and. b >= a .and. b < huge(cli%last)
            if (.not. ok) call usage_error(sub, '--rows takes FIRST:LAST (row numbers ' // &
                'from 1), not "' // v // '"')
            cli%first = int(a)
            cli%last = int(b)
        case ('--max')
            v = option_value(sub, i, nargs)
            call parse_int(v, cli%max_pulses, ok)
            if (.not. ok .or. cli%max_pulses < 1 .or. cli%max_pulses > MAX_NUMBER) &
                call usage_error(sub, '--max takes the most pulses of one frame, 1 to ' // &
                                 str(MAX_NUMBER) // ', not "' // v // '"')
        end select
    end subroutine take_option

    !> The value of option i (the next argument), or a usage error.
    function option_value(sub, i, nargs) result(v)
        character(len=*), intent(in) :: sub
        integer, intent(inout) :: i
        integer, intent(in) :: nargs
        character(len=:), allocatable :: v
        if (i >= nargs) call usage_error(sub, 'option ' // get_arg(i) // ' needs a value')
        v = get_arg(i + 1)
        if (len(v) > 2) then
            if (v(1:2) == '--') call usage_error(sub, 'option ' // get_arg(i) // &
                ' needs a value, not the option ' // v // ' (a file of that name: ./' // v // ')')
        end if
        i = i + 1
    end function option_value

    !> The one file argument of a subcommand.
    subroutine take_file(sub, file, a)
        character(len=*), intent(in) :: sub
        character(len=:), allocatable, intent(inout) :: file
        character(len=*), intent(in) :: a
        if (len(a) > 1) then
            if (a(1:1) == '-') call usage_error(sub, 'unknown option ' // a)
        end if
        if (len(a) == 0) call usage_error(sub, 'an empty file name')
        if (len(file) > 0) call usage_error(sub, 'one file at a time: ' // file // ' and ' // a)
        file = a
    end subroutine take_file

    subroutine need_file(sub, file, what)
        character(len=*), intent(in) :: sub, file, what
        if (len(file) == 0) call usage_error(sub, 'missing ' // what)
    end subroutine need_file

    !> DX, then DY, of split's move: whole numbers of pulses, negative allowed.
    subroutine take_move(cli, a, n)
        type(cli_t), intent(inout) :: cli
        character(len=*), intent(in) :: a
        integer, intent(inout) :: n
        logical :: ok
        if (n == 2) call usage_error('split', 'one move at a time: DX DY')
        call parse_int(a, cli%move(n + 1), ok)
        if (.not. ok .or. abs(cli%move(n + 1)) > MAX_NUMBER) call usage_error('split', &
            'DX and DY are whole numbers of pulses (0.01 mm), at most ' // str(MAX_NUMBER) // &
            ', not "' // a // '"')
        n = n + 1
    end subroutine take_move

    !> One line on standard error, exit status 2.
    subroutine usage_error(sub, text)
        character(len=*), intent(in) :: sub, text
        if (len(sub) > 0) then
            call say('em703 ' // sub // ': ' // text // ' (see em703 ' // sub // ' --help)')
        else
            call say('em703: ' // text // ' (see em703 --help)')
        end if
        stop 2, quiet=.true.
    end subroutine usage_error

    subroutine help(sub)
        character(len=*), intent(in) :: sub
        select case (sub)
        case ('split')
            call put([character(len=78) :: &
            'usage: em703 split [--max N] [--equal] DX DY', &
            '', &
            'Prints, one "DX DY" pair a line, the frames of a straight move of DX, DY', &
            'pulses (0.01 mm) split into as few frames of at most N pulses per axis as', &
            'possible, every division point within one pulse of the line (seed 004:', &
            'frame k of n ends at the point k/n of the move, rounded, a half towards', &
            'the start). The document''s example: em703 split --max 9999 98132 87647.', &
            '', &
            '  --max N   the most pulses of one frame (default 9999)', &
            '  --equal   every frame equal but the last, which takes up the error: the', &
            '            frame''s tangent by continued fractions (seed 004); a last line', &
            '            "# ..." gives the largest distance of a division point from', &
            '            the line, in pulses', &
            '', &
            'Exit status: 0 done, 1 no equal frames fit, 2 usage error.'])
        case ('html')
            call put([character(len=78) :: &
            'usage: em703 html JOB [-o FILE]', &
            '', &
            'Writes one self-contained HTML page (scripts, styles and data inline; it', &
            'opens from disk and fetches nothing) that runs the tapes of a job sheet', &
            '(NAME.job) on an animated coordinatograph: the punched tape scrolling', &
            'under the reader, the field with the drawing as it forms, the machine''s', &
            'state (X, Y, tool, K, cycle, frames, drawn and travel mm, minutes), and', &
            'play (x1 to x1000), pause, step, jump and the choice of tape. Each tape', &
            'runs alone from the start point, as em703 sim runs it. The page''s state', &
            'is also a JavaScript interface: window.em703 (docs/TOOLS.md).', &
            '', &
            '  -o FILE   write the page to FILE (default: standard output)', &
            '', &
            'Exit status: 0 done, 1 a bad job sheet or tape, 2 usage or I/O error.'])
        case ('check')
            call put([character(len=78) :: &
            'usage: em703 check PROGRAM [--frame address|fixed|variable]', &
            '', &
            'Reads a program of seed 004''s block format (em703 gcode --dialect', &
            'iso-1970s), as text or punched on ISO or EIA tape (em703 punch), and', &
            'checks every block as the document''s reader would: N and three digits,', &
            'increasing; the words in the order N G X Y Z I J K F S T M; dimensions', &
            'a sign and six digits, G M F S T two digits; M codes of the document''s', &
            'table; and no two G or M codes of one group in a block ("ошибка', &
            'перфоленты": G00-G09, G10-G39, G40-G59, G60-G79, G80-G99; M00/M02,', &
            'M03-M05, M06, M38-M40). Prints "FILE: P programs, B blocks, no tape', &
            'error", or a line "FILE: block Nnnn (line L): ..." for each fault. A', &
            'tape''s blank rows and delete rows (rows rubbed out) are skipped.', &
            '', &
            '  --frame F   the document''s kind of frame: address (default, the words', &
            '              with their letters), fixed (the slots N G G X Y Z I J F T M', &
            '              at their columns, 48 characters) or variable (the same', &
            '              slots, a TAB before each after N, an empty slot the', &
            '              previous block''s value); each frame is read into the', &
            '              address block it stands for, then checked as above', &
            '', &
            'Exit status: 0 no fault, 1 faults (or a row of the tape in neither code:', &
            'a parity error, or no EIA character), 2 usage or I/O error.'])
        case ('list')
            call put([character(len=78) :: &
            'usage: em703 list TAPE [--utf8] [--code 8|K|auto] [--bare]', &
            '', &
            'Decodes and checks an EM-703 tape image (.ptp, one row a byte) and prints', &
            'a line "# code C, N rows, M frames", then GM, the frames one a line in the', &
            'notation of the report (DX300 DY400 CYC8 K10 KK), GM.', &
            '', &
            '  --utf8           the report''s symbols: ΔX ΔY Ц К КК ГМ', &
            '  --code 8|K|auto  the code variant (default auto: the first digit row', &
            '                   that tells "8" from "K with control" decides)', &
            '  --bare           the frame text only, as TENZOR writes it (NAME-*.txt)', &
            '', &
            'A bad tape: the frames before the error on standard output, then', &
            '"TAPE: row N: what was found and expected" on standard error, exit 1.', &
            'Exit status: 0 good tape, 1 bad tape, 2 usage or I/O error.'])
        case ('sim')
            call put([character(len=78) :: &
            'usage: em703 sim TAPE [--scale N:D] [--start X,Y] [--svg FILE] [--tool MM]', &
            '                      [--code 8|K|auto]', &
            '', &
            'Runs the tape on the simulated coordinatograph (tool raised at the start', &
            'point; lines and travel at 5.5 m/min, arcs at 1.5 m/min) and prints', &
            '"key = value" lines: code, frames, executed, rows, tape_m, drawn_mm,', &
            'line_mm, arc_mm, travel_mm, minutes, end_x_mm, end_y_mm, tool_at_end,', &
            'xmin_mm, xmax_mm, ymin_mm, ymax_mm (mm from the start point), scale,', &
            'start_x_mm, start_y_mm, field (inside or left).', &
            '', &
            '  --scale N:D   machine scale: 1:100 1:10 1:5 1:2 1:1 2:1 5:1 50:1 100:1', &
            '                (default 1:1)', &
            '  --start X,Y   the start point on the 1200 x 1200 mm field, mm', &
            '                (default 0,0; a job sheet says start_x_mm, start_y_mm)', &
            '  --svg FILE    draw the run: strokes with the tool width, travel dashed', &
            '  --tool MM     tool width for --svg (default 0.50)', &
            '  --code        code variant, as for em703 list', &
            '', &
            'Exit status: 0 done, 1 a bad tape or the drawing leaves the field (the', &
            'frame and its row on standard error), 2 usage or I/O error.'])
        case ('svg')
            call put([character(len=78) :: &
            'usage: em703 svg JOB [-o FILE]', &
            '', &
            'Draws all tapes of a job sheet (NAME.job, beside its tapes) in one SVG:', &
            'small pads red, large pads blue, conductors green, each with its tool,', &
            'on a millimetre grid, coordinates in mm from the start point.', &
            '', &
            '  -o FILE   write the SVG to FILE (default: standard output)', &
            '', &
            'Exit status: 0 done, 1 a bad job sheet or tape, 2 usage or I/O error.'])
        case ('gcode')
            call put([character(len=78) :: &
            'usage: em703 gcode TAPE|JOB [--dialect linuxcnc|grbl|iso-1970s] [--chords TOL]', &
            '                            [--z] [--frame address|fixed|variable] [-o FILE]', &
            '', &
            'Translates a tape (or the three tapes of a job sheet NAME.job, each after', &
            'a tool change T1..T3 M06) to an ISO 6983 program: %, N numbers, G21 G90,', &
            'G00 travel, G01 lines (F5500), G02/G03 arcs with I J (F1500), the tool', &
            'down and up as M03/M05, M02, %. Origin: the start point.', &
            '', &
            '  --dialect D   linuxcnc (default, as above) or grbl: what GRBL 1.1', &
            '                accepts (no %, M0 pauses instead of tool changes, F in', &
            '                the first block, arc centres exact to GRBL''s check), or', &
            '                iso-1970s: seed 004''s block format (N and three digits,', &
            '                at most 999 blocks a program, G two digits, increments', &
            '                X+023100 in 0.001 mm, F two-digit codes of 1.12**F mm/min,', &
            '                T01 M06, the tool as Z moves; see em703 check)', &
            '  --frame F     iso-1970s only, the document''s kind of frame: address', &
            '                (default, as above), fixed (no letters: the slots', &
            '                N G G X Y Z I J F T M at fixed columns, 48 characters', &
            '                every block) or variable (the same slots, a TAB before', &
            '                each after N, a value unchanged since the block before', &
            '                left out, the block ending after its last value)', &
            '  --chords TOL  arcs as chords for line-only machines, step angle', &
            '                2 arccos(1 - TOL/R), never more than TOL mm off the arc', &
            '  --z           tool down / up as Z moves (G01 Z0.000 / G00 Z1.000)', &
            '  -o FILE       write the program to FILE (default: standard output)', &
            '', &
            'Exit status: 0 done, 1 a bad tape or job sheet, 2 usage or I/O error.'])
        case ('gerber')
            call put([character(len=78) :: &
            'usage: em703 gerber JOB [-o FILE]', &
            '', &
            'Translates the three tapes of a job sheet (NAME.job) to one Gerber', &
            'RS-274X image in mm: one circular aperture per tape (D10 small, D11', &
            'large, D12 cond) of its tool width from the job sheet; D01 draws for', &
            'the tool down, D03 flashes for dots, arcs in G75 with I J, D02 travel.', &
            '', &
            '  -o FILE   write the image to FILE (default: standard output)', &
            '', &
            'Exit status: 0 done, 1 a bad tape or job sheet, 2 usage or I/O error.'])
        case ('drill')
            call put([character(len=78) :: &
            'usage: em703 drill JOB [-o FILE]', &
            '', &
            'Writes an Excellon drill file (METRIC) with one hit per pad of the job''s', &
            'small- and large-pad tapes, in the order the tapes reach the pads (for a', &
            '1977 board every pad is a hole; for a NAME-DRILL job of gerber2deck the', &
            'hits are the board''s holes). A pad is found again from what the tape', &
            'draws: its centre, and as its hole a round pad''s diameter or a', &
            'rectangular pad''s shorter side; one tool per hole size.', &
            '', &
            '  -o FILE   write the drill file to FILE (default: standard output)', &
            '', &
            'Exit status: 0 done, 1 a bad tape or job sheet, 2 usage or I/O error.'])
        case ('punch')
            call put([character(len=78) :: &
            'usage: em703 punch --code iso|eia [-o TAPE] FILE', &
            '', &
            'Punches a text file (a G-code program, say) on 8-track tape, one byte a', &
            'row: ISO 7-bit (ASCII, even parity on track 8, LF ends a block) or EIA', &
            'RS-244 (odd parity on track 5, end of block on track 8 alone; letters', &
            'of either case), with 20 blank rows of leader and trailer. CR is dropped.', &
            '', &
            '  --code iso|eia  the tape code (required)', &
            '  -o TAPE         the tape image (default: FILE with .iso.ptp / .eia.ptp)', &
            '', &
            'A character outside the code: "FILE: line N, column C: ..." and exit 1.', &
            'Exit status: 0 done, 1 the text cannot be punched, 2 usage or I/O error.'])
        case ('view')
            call put([character(len=78) :: &
            'usage: em703 view TAPE [--code auto|em703|iso|eia] [--rows FIRST:LAST]', &
            '', &
            'Draws a tape image as punched tape, a row a line: row number, holes (o)', &
            'and the feed hole (.), the row in octal, what it means. EM-703 tapes have', &
            '5 tracks, ISO and EIA tapes 8 (auto: 5 tracks if every row fits, else', &
            'ISO for even parity, EIA for odd).', &
            '', &
            '  --code      the tape code (default auto)', &
            '  --rows A:B  only rows A to B', &
            '', &
            'Exit status: 0 done, 1 not a tape of that code, 2 usage or I/O error.'])
        case default
            call put([character(len=78) :: &
            'usage: em703 SUBCOMMAND [ARGS] (em703 SUBCOMMAND --help for each)', &
            '', &
            'The modern tools of the EM-703 tape subsystem (JINR P11-10356, 1977):', &
            '', &
            '  list TAPE [--utf8] [--code 8|K|auto] [--bare]', &
            '                                       decode and check a tape', &
            '  sim TAPE [--scale N:D] [--start X,Y] [--svg FILE] [--tool MM]', &
            '           [--code 8|K|auto]           run it on the coordinatograph', &
            '  svg JOB [-o FILE]                    draw the tapes of a job sheet', &
            '  gcode TAPE|JOB [--dialect linuxcnc|grbl|iso-1970s] [--chords TOL] [--z]', &
            '                 [--frame address|fixed|variable] [-o FILE]', &
            '                                       ISO 6983 G-code', &
            '  gerber JOB [-o FILE]                 Gerber RS-274X', &
            '  drill JOB [-o FILE]                  Excellon: a hit per pad, tour order', &
            '  punch --code iso|eia [-o TAPE] FILE  punch text on ISO or EIA tape', &
            '  view TAPE [--code auto|em703|iso|eia] [--rows FIRST:LAST]', &
            '                                       a picture of a punched tape', &
            '  html JOB [-o FILE]                   the job on an animated machine', &
            '  split [--max N] [--equal] DX DY      a long move split into frames', &
            '  check PROGRAM [--frame address|fixed|variable]', &
            '                                       seed 004''s reader: tape errors', &
            '  --version                            the version', &
            '', &
            'Exit status: 0 done, 1 the input had errors, 2 usage or I/O error.'])
        end select
    end subroutine help

    subroutine put(lines)
        character(len=*), intent(in) :: lines(:)
        integer :: i, ios
        do i = 1, size(lines)
            write(output_unit, '(a)', iostat=ios) trim(lines(i))
        end do
    end subroutine put

end module em703_cli
