!> The subcommands of the em703 command, one function each, called by
!> app/em703.f90 once src/em703/em703_cli.f90 has parsed the arguments. Each reads its files,
!> calls the library, writes its output and returns the exit status:
!> 0 done, 1 the input had errors, 2 I/O trouble. Every message goes to
!> standard error as one line naming the file and the row (or line).
module em703_commands
    use, intrinsic :: iso_fortran_env, only: int64, real64, output_unit
    use base_error, only: error_t, error_text, new_error, AT_ROW, no_memory
    use base_io, only: read_text, write_bytes, say
    use base_files, only: same_file, open_out, close_out, commit_file
    use base_sha256, only: sha256_hex
    use base_text, only: text_t, str, fixed, mm, ends_with, octal
    use em703_codec, only: frame_t, decoder_t, decoder_start, next_frame, frame_text
    use em703_sim, only: run_t, simulate_image, field_check, shift_run, MAX_DRAWN
    use em703_jobsheet, only: job_t, layer_t, read_job, NLAYERS
    use em703_svg, only: svg_run, svg_job
    use em703_gcode, only: gcode_program
    use em703_gerber, only: gerber_image
    use em703_drill, only: hole_t, find_holes, drill_program
    use em703_punch, only: punch_text, eia_char, iso_or_eia, ISO_DELETE, EIA_DELETE
    use em703_view, only: view_tape, guess_code
    use em703_split, only: frames_needed, split_frame, split_equal
    use em703_html, only: html_job
    use em703_iso, only: iso_program, iso_check, frame_kind
    implicit none
    private
    public :: run_list, run_sim, run_svg, run_gcode, run_gerber, run_drill, run_punch, run_view, &
              run_split, run_html, run_check

    integer, parameter, public :: EXIT_OK = 0, EXIT_INPUT = 1, EXIT_USAGE = 2

    !> The bytes of rows that fit 5 tracks (0..31).
    character(len=32), parameter :: FIVE_TRACK = achar(0) // achar(1) // achar(2) // achar(3) // &
        achar(4) // achar(5) // achar(6) // achar(7) // achar(8) // achar(9) // achar(10) // &
        achar(11) // achar(12) // achar(13) // achar(14) // achar(15) // achar(16) // achar(17) // &
        achar(18) // achar(19) // achar(20) // achar(21) // achar(22) // achar(23) // achar(24) // &
        achar(25) // achar(26) // achar(27) // achar(28) // achar(29) // achar(30) // achar(31)

    !> The files this run has read (outputs may not replace them).
    type :: path_t
        character(len=:), allocatable :: path
    end type path_t
    type(path_t), allocatable :: inputs(:)

contains

    !> Read a tape and run it on the simulated coordinatograph (em703_sim:
    !> the frames are decoded one at a time, none is kept); status 0, 1 (bad
    !> tape) or 2 (cannot read). With layer (a tape of a job sheet), the tape
    !> must have the size and SHA-256 the job sheet records for it, when it
    !> records them.
    subroutine load_run(path, code, run, status, layer, job_path)
        character(len=*), intent(in) :: path, code
        type(run_t), intent(out) :: run
        integer, intent(out) :: status
        type(layer_t), intent(in), optional :: layer
        character(len=*), intent(in), optional :: job_path
        type(error_t), allocatable :: err
        character(len=:), allocatable :: bytes
        call read_input(path, bytes, status)
        if (status /= EXIT_OK) return
        if (present(layer)) then
            if ((layer%bytes >= 0 .and. layer%bytes /= len(bytes)) .or. &
                (len(layer%sha256) > 0 .and. layer%sha256 /= sha256_hex(bytes))) then
                call say(path // ': the tape is not the one the job sheet ' // job_path // &
                    ' records (' // str(len(bytes)) // ' bytes, SHA-256 ' // sha256_hex(bytes) // &
                    '; the sheet says ' // str(layer%bytes) // ' bytes, ' // layer%sha256 // &
                    '): the package holds files of different runs; run tenzor again')
                status = EXIT_INPUT
                return
            end if
        end if
        call simulate_image(bytes, code, run, err)
        if (allocated(err)) then
            err%file = path
            call say(error_text(err))
            status = EXIT_INPUT
        end if
    end subroutine load_run

    !> Read an input whole (a tape image: a byte a row; or a text to
    !> punch); status 0, or 2 (cannot read: the message is said).
    subroutine read_input(path, bytes, status)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: bytes
        integer, intent(out) :: status
        type(error_t), allocatable :: err
        status = EXIT_OK
        call read_text(path, bytes, err)
        if (allocated(err)) then
            call say(error_text(err))
            status = EXIT_USAGE
            return
        end if
        call remember_input(path)
    end subroutine read_input

    !> Open an output: the file path, written whole or not at all (a fresh
    !> temporary file, renamed by close_output), or standard output when
    !> path is "" or "-". text becomes a stream into it, so that an output
    !> of any size takes a bounded buffer. False, with status 2 and a
    !> message, when path is one of the run's inputs or cannot be created;
    !> else status is left as it was.
    logical function opened(path, text, tmp, status)
        character(len=*), intent(in) :: path
        type(text_t), intent(inout) :: text
        character(len=:), allocatable, intent(out) :: tmp
        integer, intent(inout) :: status
        character(len=:), allocatable :: msg
        integer :: fd
        tmp = ''
        opened = .true.
        if (len(path) == 0 .or. path == '-') then
            flush(output_unit)
            call text%attach(1)
            return
        end if
        opened = refuse_input(path) == EXIT_OK
        if (opened) then
            call open_out(path, fd, tmp, msg)
            opened = len(msg) == 0
            if (.not. opened) call cannot_write(path, msg)
        end if
        if (.not. opened) then
            status = EXIT_USAGE
            return
        end if
        call text%attach(fd)
    end function opened

    !> End an output of opened: the rest written, the file fsynced, checked
    !> and renamed into place; on any failure the earlier file is left as it
    !> was, no temporary file is left, and the status becomes 2 (else it is
    !> left as it was).
    subroutine close_output(path, text, tmp, status)
        character(len=*), intent(in) :: path, tmp
        type(text_t), intent(inout) :: text
        integer, intent(inout) :: status
        character(len=:), allocatable :: msg
        call text%drain()
        if (text%fd == 1) then
            if (allocated(text%message)) then
                call say('em703: cannot write standard output: ' // text%message)
                status = EXIT_USAGE
            end if
            return
        end if
        if (allocated(text%message)) then
            call close_out(text%fd, tmp, -1_int64, msg)      ! abandoned: removed
            call cannot_write(path, text%message)
            status = EXIT_USAGE
            return
        end if
        call close_out(text%fd, tmp, text%written, msg)
        if (len(msg) == 0) call commit_file(tmp, path, msg)
        if (len(msg) > 0) then
            call cannot_write(path, msg)
            status = EXIT_USAGE
        end if
    end subroutine close_output

    subroutine cannot_write(path, msg)
        character(len=*), intent(in) :: path, msg
        type(error_t), allocatable :: err
        call new_error(err, 'cannot write: ' // msg)
        err%file = path
        call say(error_text(err))
    end subroutine cannot_write

    !> Status 1 (and a message naming the row) when a run executes more
    !> frames than the drawing and program writers take (MAX_DRAWN); who:
    !> the writer asked for (svg, gcode, gerber, drill, sim --svg).
    integer function too_long(path, run, who) result(status)
        character(len=*), intent(in) :: path, who
        type(run_t), intent(in) :: run
        type(error_t), allocatable :: err
        status = EXIT_OK
        if (run%executed <= MAX_DRAWN) return
        call new_error(err, 'the tape runs ' // str(run%executed) // ' frames (cycles unrolled): ' // &
            'more than the ' // str(MAX_DRAWN) // ' that ' // who // ' writes one by one ' // &
            '(sim and html take any tape)', AT_ROW, run%long_row)
        err%file = path
        call say(error_text(err))
        status = EXIT_INPUT
    end function too_long

    !> Note a file this run reads: no output may be written over it.
    subroutine remember_input(path)
        character(len=*), intent(in) :: path
        type(path_t), allocatable :: more(:)
        if (.not. allocated(inputs)) allocate(inputs(0))
        allocate(more(size(inputs) + 1))
        more(1:size(inputs)) = inputs
        more(size(more))%path = path
        call move_alloc(more, inputs)
    end subroutine remember_input

    !> EXIT_USAGE (and a message) when out is a file this run read.
    integer function refuse_input(out) result(status)
        character(len=*), intent(in) :: out
        integer :: i
        status = EXIT_OK
        if (.not. allocated(inputs)) return
        do i = 1, size(inputs)
            if (same_file(out, inputs(i)%path)) then
                call say('em703: will not write ' // out // ' over its own input ' // &
                         inputs(i)%path // '; choose another output file (-o)')
                status = EXIT_USAGE
                return
            end if
        end do
    end function refuse_input

    ! ------------------------------------------------------------------
    !> em703 list: the frames of a tape, its code variant, or its first error.
    !> The tape is decoded twice, a frame at a time: once for the head line
    !> (its counts, and the error), once for the frames.
    integer function run_list(path, code, utf8, bare) result(status)
        character(len=*), intent(in) :: path, code
        logical, intent(in) :: utf8, bare
        character(len=:), allocatable :: bytes, head, gm, tmp
        character(len=1) :: told
        type(decoder_t) :: dec
        type(frame_t) :: f
        type(error_t), allocatable :: err
        type(text_t) :: text
        logical :: got
        integer :: n
        call read_input(path, bytes, status)
        if (status /= EXIT_OK) return
        call decoder_start(dec, bytes, code, err)
        do while (.not. allocated(err))
            call next_frame(dec, bytes, f, got, err)
            if (.not. got) exit
        end do
        if (allocated(err)) then
            err%file = path
            call say(error_text(err))
            status = EXIT_INPUT
        end if
        if (.not. opened('', text, tmp, status)) return
        if (.not. bare) then
            head = '# code ' // dec%code
            if (.not. dec%told) head = head // ' (no digit row tells 8 from K)'
            head = head // ', ' // str(dec%nrows) // ' rows, ' // str(dec%nframes) // &
                   trim(merge(' frame ', ' frames', dec%nframes == 1))
            if (status /= EXIT_OK) head = head // ' before the error'
            call text%add(head)
        end if
        if (dec%opened) then
            gm = 'GM'
            if (utf8) gm = char(208) // char(147) // char(208) // char(156)   ! ГМ
            call text%add(gm)
            n = dec%nframes
            told = dec%code                        ! (dec is reset by decoder_start)
            call decoder_start(dec, bytes, told, err)
            do while (n > 0)
                call next_frame(dec, bytes, f, got, err)
                if (.not. got) exit
                call text%add(frame_text(f, utf8))
                n = n - 1
            end do
            if (status == EXIT_OK) call text%add(gm)
        end if
        call close_output('', text, tmp, status)
    end function run_list

    ! ------------------------------------------------------------------
    !> em703 sim: run a tape on the simulated coordinatograph.
    integer function run_sim(path, code, num, den, start_x, start_y, svg_path, tool) result(status)
        character(len=*), intent(in) :: path, code, svg_path
        integer, intent(in) :: num, den
        integer(int64), intent(in) :: start_x, start_y, tool
        type(run_t) :: run
        type(text_t) :: text, svg
        type(error_t), allocatable :: field_err
        character(len=:), allocatable :: tmp
        call load_run(path, code, run, status)
        if (status /= EXIT_OK) return
        call field_check(run, start_x, start_y, num, den, field_err)
        call text%add('code = ' // run%code)
        call text%add('frames = ' // str(run%nframes))
        call text%add('executed = ' // str(run%executed))
        call text%add('rows = ' // str(run%nrows))
        call text%add('tape_m = ' // fixed(run%nrows * 2.54_real64 / 1000, 3))
        call text%add('drawn_mm = ' // fixed(run%drawn_mm, 2))
        call text%add('line_mm = ' // fixed(run%line_mm, 2))
        call text%add('arc_mm = ' // fixed(run%arc_mm, 2))
        call text%add('travel_mm = ' // fixed(run%travel_mm, 2))
        call text%add('minutes = ' // fixed(run%minutes, 3))
        call text%add('end_x_mm = ' // mm(run%end_x))
        call text%add('end_y_mm = ' // mm(run%end_y))
        call text%add('tool_at_end = ' // trim(merge('down', 'up  ', run%down)))
        call text%add('xmin_mm = ' // fixed(run%xmin, 2))
        call text%add('xmax_mm = ' // fixed(run%xmax, 2))
        call text%add('ymin_mm = ' // fixed(run%ymin, 2))
        call text%add('ymax_mm = ' // fixed(run%ymax, 2))
        call text%add('scale = ' // str(num) // ':' // str(den))
        call text%add('start_x_mm = ' // mm(start_x))
        call text%add('start_y_mm = ' // mm(start_y))
        call text%add('field = ' // trim(merge('left  ', 'inside', allocated(field_err))))
        if (.not. opened('', text, tmp, status)) return
        call close_output('', text, tmp, status)
        if (len(svg_path) > 0) then
            if (too_long(path, run, 'sim --svg') /= EXIT_OK) then
                status = EXIT_INPUT
                return
            end if
            if (.not. opened(svg_path, svg, tmp, status)) return
            call svg_run(run, tool, 'EM-703 tape ' // path // ', tool ' // mm(tool) // ' mm', svg)
            call close_output(svg_path, svg, tmp, status)
            if (status /= EXIT_OK) return
        end if
        if (allocated(field_err)) then
            field_err%file = path
            call say(error_text(field_err))
            status = EXIT_INPUT
        end if
    end function run_sim

    ! ------------------------------------------------------------------
    !> The tapes of a job sheet, decoded in the job's code and run one after
    !> another (each starts where the previous one ended). Status 0, 1 or 2;
    !> complete: every tape was run and can be drawn (status 1 then means a
    !> tape that does not end at its start point, a warning the output can
    !> live with).
    subroutine load_job(path, job, runs, labels, tools, status, complete, who)
        character(len=*), intent(in) :: path
        character(len=*), intent(in) :: who   !< the command, for too_long
        type(job_t), intent(out) :: job
        type(run_t), intent(out) :: runs(NLAYERS)
        character(len=200), intent(out) :: labels(NLAYERS)
        integer(int64), intent(out) :: tools(NLAYERS)
        integer, intent(out) :: status
        logical, intent(out) :: complete
        type(error_t), allocatable :: err
        integer :: l
        integer(int64) :: ox, oy
        logical :: open_end, told8, toldk
        complete = .false.
        open_end = .false.
        call read_job(path, job, err)
        if (allocated(err)) then
            call say(error_text(err))
            status = merge(EXIT_USAGE, EXIT_INPUT, err%at == 0 .and. &
                           index(err%message, 'cannot ') == 1)
            return
        end if
        call remember_input(path)
        ox = 0
        oy = 0
        do l = 1, NLAYERS
            labels(l) = 'tape ' // job%layers(l)%key // ' ' // job%layers(l)%tape
            tools(l) = job%layers(l)%tool
            call load_run(job%layers(l)%path, job%code, runs(l), status, job%layers(l), path)
            if (status /= EXIT_OK) return
            status = too_long(job%layers(l)%path, runs(l), who)
            if (status /= EXIT_OK) return
            if (l < NLAYERS .and. (runs(l)%end_x /= 0 .or. runs(l)%end_y /= 0)) then
                call say(job%layers(l)%path // ': the tape ends at (' // mm(runs(l)%end_x) // &
                    ', ' // mm(runs(l)%end_y) // ') mm from its start point, not at it: ' // &
                    'the next tape starts there')
                open_end = .true.
            end if
            call shift_run(runs(l), ox, oy)
            ox = runs(l)%end_x
            oy = runs(l)%end_y
        end do
        complete = .true.
        if (open_end) status = EXIT_INPUT
        ! A job sheet without a code line: for the outputs' headings, the code
        ! the tapes told (a tape without a digit 3, 5, 6 or 9 tells neither)
        if (job%code == 'auto') then
            told8 = any(runs%evidence > 0 .and. runs%code == '8')
            toldk = any(runs%evidence > 0 .and. runs%code == 'K')
            if (told8 .and. toldk) then
                job%code = '8 and K'
            else if (told8) then
                job%code = '8'
            else if (toldk) then
                job%code = 'K'
            else
                job%code = '8 or K'
            end if
        end if
    end subroutine load_job

    !> em703 svg: all tapes of a job in one drawing.
    integer function run_svg(path, out) result(status)
        character(len=*), intent(in) :: path, out
        type(job_t) :: job
        type(run_t) :: runs(NLAYERS)
        character(len=200) :: labels(NLAYERS)
        integer(int64) :: tools(NLAYERS)
        type(text_t) :: text
        character(len=5) :: keys(NLAYERS)
        character(len=:), allocatable :: tmp
        integer :: l
        logical :: complete
        call load_job(path, job, runs, labels, tools, status, complete, 'svg')
        if (.not. complete) return
        do l = 1, NLAYERS
            keys(l) = job%layers(l)%key
        end do
        if (.not. opened(out, text, tmp, status)) return
        call svg_job(runs, tools, keys, 'EM-703 job ' // job%name // ': small ' // mm(tools(1)) // &
            ' mm (red), large ' // mm(tools(2)) // ' mm (blue), cond ' // mm(tools(3)) // &
            ' mm (green)', text)
        call close_output(out, text, tmp, status)
    end function run_svg

    !> em703 gcode: a tape or a job as an ISO 6983 program; frame: the kind
    !> of frame of dialect iso-1970s ("address", "fixed", "variable").
    integer function run_gcode(path, chord_tol, use_z, dialect, out, frame) result(status)
        character(len=*), intent(in) :: path, dialect, out, frame
        real(real64), intent(in) :: chord_tol
        logical, intent(in) :: use_z
        type(job_t) :: job
        type(run_t) :: runs(NLAYERS)
        character(len=200) :: labels(NLAYERS)
        integer(int64) :: tools(NLAYERS)
        type(text_t) :: text
        character(len=:), allocatable :: tmp, title
        type(error_t), allocatable :: err
        logical :: complete
        if (ends_with(path, '.job')) then
            call load_job(path, job, runs, labels, tools, status, complete, 'gcode')
            if (.not. complete) return
            if (.not. opened(out, text, tmp, status)) return
            if (dialect == 'iso-1970s') then
                call iso_program(runs, labels, 'EM-703 job ' // job%name // ', code ' // job%code, &
                                 chord_tol, text, err, frame_kind(frame))
            else
                call gcode_program(runs, labels, tools, 'EM-703 job ' // job%name // ', code ' // &
                                   job%code, chord_tol, use_z, text, dialect)
            end if
        else
            call load_run(path, 'auto', runs(1), status)
            if (status /= EXIT_OK) return
            status = too_long(path, runs(1), 'gcode')
            if (status /= EXIT_OK) return
            labels(1) = 'tape ' // path
            tools(1) = 0
            if (.not. opened(out, text, tmp, status)) return
            title = 'EM-703 tape, code ' // runs(1)%code // ', ' // str(runs(1)%nframes) // &
                    trim(merge(' frame ', ' frames', runs(1)%nframes == 1))
            if (dialect == 'iso-1970s') then
                call iso_program(runs(1:1), labels(1:1), title, chord_tol, text, err, &
                                 frame_kind(frame))
            else
                call gcode_program(runs(1:1), labels(1:1), tools(1:1), title, chord_tol, use_z, &
                                   text, dialect)
            end if
        end if
        if (allocated(err)) then
            call say(error_text(err))
            text%message = 'abandoned'
            status = EXIT_INPUT
        end if
        call close_output(out, text, tmp, status)
    end function run_gcode

    !> em703 gerber: the tapes of a job as one RS-274X image.
    integer function run_gerber(path, out) result(status)
        character(len=*), intent(in) :: path, out
        type(job_t) :: job
        type(run_t) :: runs(NLAYERS)
        character(len=200) :: labels(NLAYERS)
        integer(int64) :: tools(NLAYERS)
        type(text_t) :: text
        character(len=:), allocatable :: tmp
        integer :: l
        logical :: complete
        real(real64) :: far
        call load_job(path, job, runs, labels, tools, status, complete, 'gerber')
        if (.not. complete) return
        do l = 1, NLAYERS
            far = max(abs(runs(l)%xmin), abs(runs(l)%xmax), abs(runs(l)%ymin), abs(runs(l)%ymax))
            if (far > 999999.999999_real64) then
                call say(job%layers(l)%path // ': the drawing reaches ' // fixed(far, 2) // &
                         ' mm from the start point, beyond the 999999.999999 mm that the ' // &
                         'Gerber 6.6 format holds')
                status = EXIT_INPUT
                return
            end if
        end do
        if (.not. opened(out, text, tmp, status)) return
        call gerber_image(runs, labels, tools, 'EM-703 job ' // job%name // ', code ' // &
                          job%code, text)
        call close_output(out, text, tmp, status)
    end function run_gerber

    !> em703 drill: the pads of a job's pad tapes as an Excellon drill file.
    integer function run_drill(path, out) result(status)
        character(len=*), intent(in) :: path, out
        type(job_t) :: job
        type(run_t) :: runs(NLAYERS)
        character(len=200) :: labels(NLAYERS)
        integer(int64) :: tools(NLAYERS)
        type(text_t) :: text
        type(hole_t), allocatable :: holes(:)
        character(len=:), allocatable :: tmp
        integer :: l, n
        logical :: complete
        call load_job(path, job, runs, labels, tools, status, complete, 'drill')
        if (.not. complete) return
        n = 0
        allocate(holes(0))
        do l = 1, NLAYERS
            if (job%layers(l)%key == 'cond') cycle
            call find_holes(runs(l), tools(l), holes, n)
        end do
        if (.not. opened(out, text, tmp, status)) return
        call drill_program(holes(1:n), 'EM-703 job ' // job%name // ': ' // str(n) // &
                           trim(merge(' hole  ', ' holes ', n == 1)) // &
                           ' of the small- and large-pad tapes', text)
        call close_output(out, text, tmp, status)
    end function run_drill

    !> em703 html: one page that runs the tapes of a job on an animated
    !> coordinatograph. Every tape is decoded and run (each alone from the
    !> start point, as em703 sim runs it) before the page is opened, so a
    !> bad tape stops the command at its row and leaves no page.
    integer function run_html(path, out) result(status)
        character(len=*), intent(in) :: path, out
        type(job_t) :: job
        type(run_t) :: runs(NLAYERS)
        type(error_t), allocatable :: err
        type(text_t) :: text
        character(len=:), allocatable :: tmp
        integer :: l
        call read_job(path, job, err)
        if (allocated(err)) then
            call say(error_text(err))
            status = merge(EXIT_USAGE, EXIT_INPUT, err%at == 0 .and. &
                           index(err%message, 'cannot ') == 1)
            return
        end if
        call remember_input(path)
        do l = 1, NLAYERS
            call load_run(job%layers(l)%path, job%code, runs(l), status, job%layers(l), path)
            if (status /= EXIT_OK) return
        end do
        if (.not. opened(out, text, tmp, status)) return
        call html_job(job, runs, text)
        call close_output(out, text, tmp, status)
    end function run_html

    ! ------------------------------------------------------------------
    !> em703 punch: text onto an ISO 7-bit or EIA RS-244 tape image.
    integer function run_punch(code, path, out) result(status)
        character(len=*), intent(in) :: code, path, out
        character(len=:), allocatable :: text, target
        integer, allocatable :: rows(:)
        type(error_t), allocatable :: err
        integer :: k
        status = EXIT_OK
        call read_input(path, text, status)
        if (status /= EXIT_OK) return
        call punch_text(text, code, rows, err)
        if (allocated(err)) then
            err%file = path
            call say(error_text(err))
            status = EXIT_INPUT
            return
        end if
        target = out
        if (len(target) == 0) then
            k = index(path, '.', back=.true.)
            if (k <= index(path, '/', back=.true.) + 1) k = len(path) + 1
            target = path(1:k - 1) // '.' // code // '.ptp'
        end if
        status = refuse_input(target)
        if (status /= EXIT_OK) return
        call write_bytes(target, rows, err)
        if (allocated(err)) then
            call say(error_text(err))
            status = EXIT_USAGE
        end if
    end function run_punch

    !> em703 view: a picture of any tape image; code "auto", "em703", "iso", "eia".
    integer function run_view(path, code, first, last) result(status)
        character(len=*), intent(in) :: path, code
        integer, intent(in) :: first, last
        character(len=:), allocatable :: bytes, c, tmp
        type(error_t), allocatable :: err
        type(text_t) :: text
        integer :: row
        call read_input(path, bytes, status)
        if (status /= EXIT_OK) return
        if (first > 1 .and. first > len(bytes)) then
            call say(path // ': --rows ' // str(first) // ':' // str(last) // ' begins after ' // &
                     'the tape''s last row, ' // str(len(bytes)) // ' (rows are numbered from 1)')
            status = EXIT_USAGE
            return
        end if
        c = code
        if (c == 'auto') c = guess_code(bytes)
        row = 0
        if (c == 'em703') row = verify(bytes, FIVE_TRACK)
        if (row > 0) then
            call new_error(err, 'holes beyond track 5 (octal ' // octal(iachar(bytes(row:row)), 3) // &
                           '): not an EM-703 tape (--code iso or eia for a tape of 7 or 8 tracks)', &
                           AT_ROW, row)
            err%file = path
            call say(error_text(err))
            status = EXIT_INPUT
            return
        end if
        if (.not. opened('', text, tmp, status)) return
        call view_tape(bytes, c, first, last, text)
        call close_output('', text, tmp, status)
    end function run_view

    ! ------------------------------------------------------------------
    !> em703 split: the frames of the straight move (dx, dy) pulses, at most
    !> max_pulses per axis each (em703_split), one "DX DY" pair a line, each
    !> written as it is found.
    integer function run_split(dx, dy, max_pulses, equal) result(status)
        integer(int64), intent(in) :: dx, dy, max_pulses
        logical, intent(in), optional :: equal
        integer(int64) :: k, n, fx, fy, lx, ly
        real(real64) :: dev
        logical :: ok
        type(text_t) :: text
        character(len=:), allocatable :: tmp, line
        status = EXIT_OK
        if (present(equal)) then
            if (equal) then
                call split_equal(dx, dy, max_pulses, fx, fy, n, lx, ly, dev, ok)
                if (.not. ok) then
                    call say('em703 split: no equal frames of at most ' // str(max_pulses) // &
                             ' pulses fit the move (' // str(dx) // ', ' // str(dy) // ')')
                    status = EXIT_INPUT
                    return
                end if
                if (.not. opened('', text, tmp, status)) return
                do k = 1, n
                    call text%add(str(fx) // ' ' // str(fy))
                end do
                if (lx /= 0 .or. ly /= 0) call text%add(str(lx) // ' ' // str(ly))
                k = n + merge(1, 0, lx /= 0 .or. ly /= 0)
                if (n > 0) then
                    line = '# ' // str(k) // trim(merge(' frame: ', ' frames:', k == 1)) // ' ' // &
                           str(n) // ' of ' // str(fx) // ' ' // str(fy)
                else
                    line = '# no frame'
                end if
                if (lx /= 0 .or. ly /= 0) line = line // ', the last ' // str(lx) // ' ' // str(ly)
                call text%add(line // '; largest distance of a division point from the line ' // &
                              fixed(dev, 6) // ' pulses')
                call close_output('', text, tmp, status)
                return
            end if
        end if
        if (.not. opened('', text, tmp, status)) return
        n = frames_needed(dx, dy, max_pulses)
        do k = 1, n
            call split_frame(dx, dy, k, n, fx, fy)
            call text%add(str(fx) // ' ' // str(fy))
        end do
        call close_output('', text, tmp, status)
    end function run_split

    ! ------------------------------------------------------------------
    !> em703 check: a program of seed 004's block format in frames of kind
    !> frame ("address", "fixed", "variable"), as text or as a tape image
    !> (a byte 0 or above 127): ISO when most punched rows have an even
    !> number of holes (track 8 dropped), else EIA (read back to ASCII, the
    !> letters upper case); blank rows and delete rows (a row rubbed out)
    !> skipped, a row of the wrong parity or no EIA code an error. Checked
    !> block by block (em703_iso).
    integer function run_check(path, frame) result(status)
        character(len=*), intent(in) :: path, frame
        character(len=:), allocatable :: bytes, prog, tmp, lines, why
        type(text_t) :: msgs, text
        integer :: i, c, n, nerr, nprog, nblocks, k, j, high, nl, nrows, st
        integer, allocatable :: rows(:)
        logical :: tape, eia
        call read_input(path, bytes, status)
        if (status /= EXIT_OK) return
        tape = index(bytes, achar(0)) > 0
        high = 0
        nl = 0
        do i = 1, len(bytes)
            c = iachar(bytes(i:i))
            if (c > 127) then
                high = i
                exit
            end if
            if (c == 10) nl = nl + 1
        end do
        eia = iso_or_eia(bytes) == 'eia'
        ! a file without a blank row is a tape image for its rows with track 8
        ! (bytes above 127), which a text that is not ASCII also has (UTF-8
        ! letters in a comment, say): a row's fault then says why the file was
        ! read as a tape
        why = ''
        if (.not. tape .and. high > 0) then
            tape = .true.
            why = ' (read as a tape image for its bytes above 127, the first at row ' // &
                  str(high) // ', line ' // str(nl + 1) // ' as text: ' // &
                  'a program as text must be ASCII)'
        end if
        if (tape) then
            allocate(character(len=len(bytes)) :: prog, stat=st)
            if (st /= 0) call no_memory('the program read from the tape', int(len(bytes), int64))
            ! rows(l): the tape row where line l of the text read from it
            ! starts, for the faults (a line ends at each end of block)
            allocate(rows(64))
            nrows = 0
            n = 0
            do i = 1, len(bytes)
                c = iachar(bytes(i:i))
                if (c == 0 .or. c == merge(EIA_DELETE, ISO_DELETE, eia)) cycle
                if (eia) then
                    if (mod(popcnt(c), 2) == 0) then
                        call say(path // ': row ' // str(i) // ': parity error (even number of ' // &
                                 'holes): not an EIA tape, or a misread row' // why)
                        status = EXIT_INPUT
                        return
                    end if
                    c = eia_char(c)
                    if (c < 0) then
                        call say(path // ': row ' // str(i) // ': octal ' // &
                                 octal(iachar(bytes(i:i)), 3) // ' is no EIA RS-244 code: not an ' // &
                                 'EIA tape, or a misread row' // why)
                        status = EXIT_INPUT
                        return
                    end if
                else
                    if (mod(popcnt(c), 2) == 1) then
                        call say(path // ': row ' // str(i) // ': parity error (odd number of ' // &
                                 'holes): not an ISO tape, or a misread row' // why)
                        status = EXIT_INPUT
                        return
                    end if
                end if
                if (n == 0) then
                    call start_line(i)
                else if (prog(n:n) == achar(10)) then
                    call start_line(i)
                end if
                n = n + 1
                prog(n:n) = achar(iand(c, 127))
            end do
            prog = prog(1:n)
            call iso_check(prog, msgs, nerr, nprog, nblocks, frame_kind(frame), rows(1:nrows))
        else
            prog = bytes
            call iso_check(prog, msgs, nerr, nprog, nblocks, frame_kind(frame))
        end if
        if (nerr == 0 .and. nprog == 0) then
            call say(path // ': no program in it: a program is a line "%", its numbered ' // &
                     'blocks (N001 ...), and "%"')
            status = EXIT_INPUT
            return
        end if
        if (nerr > 0) then
            lines = msgs%value()
            k = 1
            do while (k <= len(lines))
                j = index(lines(k:), achar(10))
                if (j == 0) j = len(lines) - k + 2
                call say(path // ': ' // lines(k:k + j - 2))
                k = k + j
            end do
            status = EXIT_INPUT
            return
        end if
        if (.not. opened('', text, tmp, status)) return
        call text%add(path // ': ' // str(nprog) // trim(merge(' program, ', ' programs,', &
            nprog == 1)) // ' ' // str(nblocks) // trim(merge(' block, ', ' blocks,', nblocks == 1)) // &
            ' no tape error')
        call close_output('', text, tmp, status)

    contains

        !> Line nrows + 1 of the text read from the tape starts at its row.
        subroutine start_line(row)
            integer, intent(in) :: row
            integer, allocatable :: more(:)
            if (nrows == size(rows)) then
                allocate(more(2 * size(rows)), stat=st)
                if (st /= 0) call no_memory('the rows of the lines', 8 * int(size(rows), int64))
                more(1:nrows) = rows(1:nrows)
                call move_alloc(more, rows)
            end if
            nrows = nrows + 1
            rows(nrows) = row
        end subroutine start_line
    end function run_check

end module em703_commands
