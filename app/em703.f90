!> em703: the modern tools around the EM-703 tapes. This program only reads
!> the command line (src/em703/em703_cli.f90) and dispatches to the
!> subcommand's function (src/em703/em703_commands.f90); see --help and
!> docs/TOOLS.md. Exit status: 0 done, 1 the input had errors, 2 usage or I/O.
program em703
    use em703_cli, only: cli_t, parse_command_line
    use em703_commands, only: run_list, run_sim, run_svg, run_gcode, run_gerber, run_drill, &
                              run_punch, run_view, run_split, run_html, run_check
    implicit none

    type(cli_t) :: c
    integer :: status

    call parse_command_line(c)
    select case (c%command)
    case ('list')
        status = run_list(c%file, c%code, c%utf8, c%bare)
    case ('sim')
        status = run_sim(c%file, c%code, c%num, c%den, c%start_x, c%start_y, c%svg, c%tool)
    case ('svg')
        status = run_svg(c%file, c%out)
    case ('gcode')
        status = run_gcode(c%file, c%chord_tol, c%use_z, c%dialect, c%out, c%frame)
    case ('gerber')
        status = run_gerber(c%file, c%out)
    case ('drill')
        status = run_drill(c%file, c%out)
    case ('punch')
        status = run_punch(c%code, c%file, c%out)
    case ('view')
        status = run_view(c%file, c%code, c%first, c%last)
    case ('html')
        status = run_html(c%file, c%out)
    case ('split')
        status = run_split(c%move(1), c%move(2), c%max_pulses, c%equal)
    case ('check')
        status = run_check(c%file, c%frame)
    case default
        status = 2          ! parse_command_line accepts no other subcommand
    end select
    if (status /= 0) stop status, quiet=.true.

end program em703
