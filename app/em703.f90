!> em703: the modern tools around the EM-703 tapes. This program only parses
!> the command line and dispatches to src/em703_commands.f90; see --help and
!> docs/TOOLS.md. Exit status: 0 done, 1 the input had errors, 2 usage or I/O.
program em703
    use, intrinsic :: iso_fortran_env, only: int64, real64, output_unit
    use em703_commands, only: run_list, run_sim, run_svg, run_gcode, run_gerber, run_punch, &
                              run_view, say
    use em703_text, only: parse_int, parse_mm, parse_real
    use em703_jobsheet, only: parse_scale, machine_scale
    use em703_split, only: split_move
    implicit none

    character(len=:), allocatable :: command, arg
    integer :: nargs, status

    nargs = command_argument_count()
    if (nargs == 0) call usage_error('', 'no subcommand')
    command = get_arg(1)
    select case (command)
    case ('-h', '--help', 'help')
        call help('')
        stop 0, quiet=.true.
    case ('list')
        status = do_list()
    case ('sim')
        status = do_sim()
    case ('svg')
        status = do_job('svg')
    case ('gcode')
        status = do_gcode()
    case ('gerber')
        status = do_job('gerber')
    case ('punch')
        status = do_punch()
    case ('view')
        status = do_view()
    case ('split')
        status = do_split()
    case default
        call usage_error('', 'unknown subcommand "' // command // '"')
    end select
    if (status /= 0) stop status, quiet=.true.

contains

    function get_arg(k) result(s)
        integer, intent(in) :: k
        character(len=:), allocatable :: s
        integer :: n
        call get_command_argument(k, length=n)
        allocate(character(len=n) :: s)
        if (n > 0) call get_command_argument(k, s)
    end function get_arg

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

    !> The value of option i (the next argument), or a usage error.
    function option_value(sub, i) result(v)
        character(len=*), intent(in) :: sub
        integer, intent(inout) :: i
        character(len=:), allocatable :: v
        if (i >= nargs) call usage_error(sub, 'option ' // get_arg(i) // ' needs a value')
        i = i + 1
        v = get_arg(i)
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

    function tape_code(sub, v) result(c)
        character(len=*), intent(in) :: sub, v
        character(len=:), allocatable :: c
        select case (v)
        case ('8', 'K', 'auto')
            c = v
        case ('k')
            c = 'K'
        case default
            call usage_error(sub, '--code takes 8, K or auto, not "' // v // '"')
        end select
    end function tape_code

    integer function do_list()
        character(len=:), allocatable :: file, code
        logical :: utf8, bare
        integer :: i
        file = ''
        code = 'auto'
        utf8 = .false.
        bare = .false.
        i = 2
        do while (i <= nargs)
            arg = get_arg(i)
            select case (arg)
            case ('-h', '--help')
                call help('list')
                stop 0, quiet=.true.
            case ('--utf8')
                utf8 = .true.
            case ('--bare')
                bare = .true.
            case ('--code')
                code = tape_code('list', option_value('list', i))
            case default
                call take_file('list', file, arg)
            end select
            i = i + 1
        end do
        call need_file('list', file, 'TAPE')
        do_list = run_list(file, code, utf8, bare)
    end function do_list

    integer function do_sim()
        character(len=:), allocatable :: file, code, svg, v
        integer :: i, num, den, p
        integer(int64) :: sx, sy, tool
        logical :: ok
        file = ''
        code = 'auto'
        svg = ''
        num = 1
        den = 1
        sx = 0
        sy = 0
        tool = 50
        i = 2
        do while (i <= nargs)
            arg = get_arg(i)
            select case (arg)
            case ('-h', '--help')
                call help('sim')
                stop 0, quiet=.true.
            case ('--scale')
                v = option_value('sim', i)
                call parse_scale(v, num, den, ok)
                if (ok) ok = machine_scale(num, den)
                if (.not. ok) call usage_error('sim', '--scale takes one of the machine''s ' // &
                    'scales 1:100 1:10 1:5 1:2 1:1 2:1 5:1 50:1 100:1, not "' // v // '"')
            case ('--start')
                v = option_value('sim', i)
                p = index(v, ',')
                ok = p > 0
                if (ok) call parse_mm(v(1:p - 1), sx, ok)
                if (ok) call parse_mm(v(p + 1:), sy, ok)
                if (ok) ok = sx >= 0 .and. sx <= 120000 .and. sy >= 0 .and. sy <= 120000
                if (.not. ok) call usage_error('sim', '--start takes X,Y in mm on the field ' // &
                    '(0 to 1200, two decimals), not "' // v // '"')
            case ('--svg')
                svg = option_value('sim', i)
                if (len(svg) == 0) call usage_error('sim', '--svg needs a file name')
            case ('--tool')
                v = option_value('sim', i)
                call parse_mm(v, tool, ok)
                if (.not. ok .or. tool <= 0 .or. tool > 2000) call usage_error('sim', &
                    '--tool takes the tool width in mm (0.01 to 20.00), not "' // v // '"')
            case ('--code')
                code = tape_code('sim', option_value('sim', i))
            case default
                call take_file('sim', file, arg)
            end select
            i = i + 1
        end do
        call need_file('sim', file, 'TAPE')
        do_sim = run_sim(file, code, num, den, sx, sy, svg, tool)
    end function do_sim

    !> em703 svg|gerber [-o FILE] JOB: the two commands that draw a whole job.
    integer function do_job(sub)
        character(len=*), intent(in) :: sub
        character(len=:), allocatable :: file, out
        integer :: i
        file = ''
        out = ''
        i = 2
        do while (i <= nargs)
            arg = get_arg(i)
            select case (arg)
            case ('-h', '--help')
                call help(sub)
                stop 0, quiet=.true.
            case ('-o', '--output')
                out = option_value(sub, i)
            case default
                call take_file(sub, file, arg)
            end select
            i = i + 1
        end do
        call need_file(sub, file, 'JOB (a job sheet NAME.job)')
        if (sub == 'svg') then
            do_job = run_svg(file, out)
        else
            do_job = run_gerber(file, out)
        end if
    end function do_job

    integer function do_gcode()
        character(len=:), allocatable :: file, out, v
        real(real64) :: tol
        logical :: use_z, ok
        integer :: i
        file = ''
        out = ''
        tol = 0
        use_z = .false.
        i = 2
        do while (i <= nargs)
            arg = get_arg(i)
            select case (arg)
            case ('-h', '--help')
                call help('gcode')
                stop 0, quiet=.true.
            case ('-o', '--output')
                out = option_value('gcode', i)
            case ('--z')
                use_z = .true.
            case ('--chords')
                v = option_value('gcode', i)
                call parse_real(v, tol, ok)
                if (.not. ok .or. tol < 0.001_real64 .or. tol > 100) call usage_error('gcode', &
                    '--chords takes the tolerance in mm (0.001 to 100), not "' // v // '"')
            case default
                call take_file('gcode', file, arg)
            end select
            i = i + 1
        end do
        call need_file('gcode', file, 'TAPE or JOB')
        do_gcode = run_gcode(file, tol, use_z, out)
    end function do_gcode

    integer function do_punch()
        character(len=:), allocatable :: file, out, code, v
        integer :: i
        file = ''
        out = ''
        code = ''
        i = 2
        do while (i <= nargs)
            arg = get_arg(i)
            select case (arg)
            case ('-h', '--help')
                call help('punch')
                stop 0, quiet=.true.
            case ('-o', '--output')
                out = option_value('punch', i)
                if (len(out) == 0) call usage_error('punch', '-o needs a file name')
            case ('--code')
                v = option_value('punch', i)
                select case (v)
                case ('iso', 'ISO')
                    code = 'iso'
                case ('eia', 'EIA')
                    code = 'eia'
                case default
                    call usage_error('punch', '--code takes iso or eia, not "' // v // '"')
                end select
            case default
                call take_file('punch', file, arg)
            end select
            i = i + 1
        end do
        if (len(code) == 0) call usage_error('punch', 'missing --code iso|eia')
        call need_file('punch', file, 'FILE (the text to punch)')
        do_punch = run_punch(code, file, out)
    end function do_punch

    integer function do_view()
        character(len=:), allocatable :: file, code, v
        integer :: i, first, last, p
        integer(int64) :: a, b
        logical :: ok
        file = ''
        code = 'auto'
        first = 1
        last = huge(last)
        i = 2
        do while (i <= nargs)
            arg = get_arg(i)
            select case (arg)
            case ('-h', '--help')
                call help('view')
                stop 0, quiet=.true.
            case ('--code')
                v = option_value('view', i)
                select case (v)
                case ('auto', 'em703', 'iso', 'eia')
                    code = v
                case default
                    call usage_error('view', '--code takes auto, em703, iso or eia, not "' // v // '"')
                end select
            case ('--rows')
                v = option_value('view', i)
                p = index(v, ':')
                ok = p > 1 .and. p < len(v)
                if (ok) call parse_int(v(1:p - 1), a, ok)
                if (ok) call parse_int(v(p + 1:), b, ok)
                if (ok) ok = a >= 1 .and. b >= a .and. b < huge(last)
                if (.not. ok) call usage_error('view', '--rows takes FIRST:LAST (row numbers ' // &
                    'from 1), not "' // v // '"')
                first = int(a)
                last = int(b)
            case default
                call take_file('view', file, arg)
            end select
            i = i + 1
        end do
        call need_file('view', file, 'TAPE')
        do_view = run_view(file, code, first, last)
    end function do_view

    !> em703 split [--max N] DX DY: the frames of a long move, one pair a line.
    integer function do_split()
        character(len=:), allocatable :: v
        integer(int64) :: nmax, d(2)
        integer(int64), allocatable :: dxs(:), dys(:)
        integer :: i, nd, k
        logical :: ok
        character(len=48) :: line
        nmax = 9999
        nd = 0
        i = 2
        do while (i <= nargs)
            arg = get_arg(i)
            select case (arg)
            case ('-h', '--help')
                call help('split')
                stop 0, quiet=.true.
            case ('--max')
                v = option_value('split', i)
                call parse_int(v, nmax, ok)
                if (.not. ok .or. nmax < 1 .or. nmax > 999999999_int64) call usage_error('split', &
                    '--max takes the most pulses of one frame, 1 to 999999999, not "' // v // '"')
            case default
                if (nd == 2) call usage_error('split', 'one move at a time: DX DY')
                call parse_int(arg, d(nd + 1), ok)
                if (.not. ok .or. abs(d(min(nd + 1, 2))) > 999999999_int64) call usage_error( &
                    'split', 'DX and DY are whole numbers of pulses (0.01 mm), at most ' // &
                    '999999999, not "' // arg // '"')
                nd = nd + 1
            end select
            i = i + 1
        end do
        if (nd /= 2) call usage_error('split', 'needs DX and DY, in pulses')
        call split_move(d(1), d(2), nmax, dxs, dys)
        do k = 1, size(dxs)
            write(line, '(i0, 1x, i0)') dxs(k), dys(k)
            call put([line])
        end do
        do_split = 0
    end function do_split

    subroutine help(sub)
        character(len=*), intent(in) :: sub
        select case (sub)
        case ('split')
            call put([character(len=78) :: &
            'usage: em703 split [--max N] DX DY', &
            '', &
            'Prints, one "DX DY" pair a line, the frames of a straight move of DX, DY', &
            'pulses (0.01 mm) split into as few frames of at most N pulses per axis as', &
            'possible, every division point within one pulse of the line (seed 004:', &
            'frame k of n ends at the point k/n of the move, rounded, a half towards', &
            'the start). The document''s example: em703 split --max 9999 98132 87647.', &
            '', &
            '  --max N   the most pulses of one frame (default 9999)', &
            '', &
            'Exit status: 0 done, 2 usage error.'])
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
            'usage: em703 gcode TAPE|JOB [--chords TOL] [--z] [-o FILE]', &
            '', &
            'Translates a tape (or the three tapes of a job sheet NAME.job, each after', &
            'a tool change T1..T3 M06) to an ISO 6983 program: %, N numbers, G21 G90,', &
            'G00 travel, G01 lines (F5500), G02/G03 arcs with I J (F1500), the tool', &
            'down and up as M03/M05, M02, %. Origin: the start point.', &
            '', &
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
            '  list TAPE [--utf8]                   decode and check a tape', &
            '  sim TAPE [--scale N:D] [--start X,Y] [--svg FILE]', &
            '                                       run it on the coordinatograph', &
            '  svg JOB [-o FILE]                    draw the tapes of a job sheet', &
            '  gcode TAPE|JOB [--chords TOL] [--z] [-o FILE]', &
            '                                       ISO 6983 G-code', &
            '  gerber JOB [-o FILE]                 Gerber RS-274X', &
            '  punch --code iso|eia [-o TAPE] FILE  punch text on ISO or EIA tape', &
            '  view TAPE                            a picture of a punched tape', &
            '  split [--max N] DX DY                a long move split into frames', &
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

end program em703
