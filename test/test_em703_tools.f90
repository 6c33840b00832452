!> Fortran tests of the em703 library: the codec in both variants (the
!> report's examples and every class of error, with its row), the simulator
!> (cycles, arcs, circles, dots, the field), the translators (SVG, G-code with
!> and without chords, Gerber), the ISO and EIA punch, the tape picture and
!> the job sheet. Expected values come from the report and docs/, worked by hand.
program test_em703_tools
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use checks, only: check, check_int, check_str, summary
    use base_error, only: error_t, error_text
    use base_text, only: text_t, str, fixed, mm, octal, parse_int, parse_mm, parse_real
    use em703_codec, only: frame_t, tape_t, decode_tape, encode_tape, frame_text, tape_text, &
                           on_circle
    use em703_html, only: html_job, json_string
    use em703_sim, only: simulate_image
    use em703_sim, only: run_t, seg_t, simulate, field_check, run_segments, seg_box, SEG_ARC, &
                         SEG_LINE, SEG_DOT, SEG_TRAVEL, SEG_RAISE, PI
    use em703_svg, only: svg_run
    use em703_gcode, only: gcode_program, chord_count, ROUNDING
    use em703_gerber, only: gerber_image
    use em703_punch, only: punch_text, iso_row, eia_row, eia_meaning, iso_meaning, LEADER, eia_char, &
                           iso_or_eia, EIA_DELETE
    use em703_view, only: view_tape, guess_code
    use em703_jobsheet, only: job_t, read_job, parse_scale, machine_scale
    use base_io, only: write_text
    use em703_split, only: split_move, split_equal
    use em703_iso, only: iso_program, iso_check, geometric_code, signed_digits, g_group, m_group
    use base_sha256, only: sha256_hex
    use base_files, only: write_whole, same_file, open_out, write_out, write_back, &
                          close_out, commit_file, discard_file
    use, intrinsic :: iso_c_binding, only: c_long_long
    implicit none

    call test_decode_report_example3()
    call test_codes_round_trip()
    call test_decode_errors()
    call test_frame_text()
    call test_on_circle()
    call test_sim_saw_cycle()
    call test_sim_arcs_and_circles()
    call test_sim_dots_and_field()
    call test_sim_cycles_are_not_unrolled()
    call test_svg()
    call test_html()
    call test_gcode()
    call test_gcode_chords()
    call test_gerber()
    call test_punch_iso()
    call test_punch_eia()
    call test_view()
    call test_jobsheet()
    call test_split_seed004()
    call test_split_equal_seed004()
    call test_iso_block_format()
    call test_text_helpers()
    call test_sha256()
    call test_whole_files()
    call test_staged_files()
    if (summary() /= 0) stop 1, quiet=.true.

contains

    function fr(x, y, dx, dy, cyc, k) result(f)
        integer, intent(in) :: x, y, dx, dy, cyc, k
        type(frame_t) :: f
        f%x = x
        f%y = y
        f%dx = dx
        f%dy = dy
        f%cyc = cyc
        f%k = k
    end function fr

    !> Rows 21..56 of docs/TAPE.md's picture (Example 3 as TENZOR punches it).
    function example3_rows() result(rows)
        integer, allocatable :: rows(:)
        integer :: i
        rows = [(0, i = 1, 20), int(o'37'), &
                int(o'12'), 2, 0, 0, 0, int(o'20'), int(o'14'), 2, 0, 0, 0, &
                int(o'21'), int(o'14'), 2, 0, 0, 0, int(o'16'), 1, 3, int(o'17'), &
                int(o'20'), 2, 0, 0, 0, int(o'21'), 2, 0, 0, 0, int(o'16'), 2, 0, int(o'17'), &
                int(o'37'), (0, i = 1, 20)]
    end function example3_rows

    subroutine decode_expect_error(rows, code, row, fragment, what)
        integer, intent(in) :: rows(:)
        character(len=*), intent(in) :: code, fragment, what
        integer, intent(in) :: row
        type(tape_t) :: tape
        type(error_t), allocatable :: err
        call decode_tape(rows, code, tape, err)
        call check(allocated(err), what // ': an error')
        if (.not. allocated(err)) return
        call check_int(err%number, row, what // ': the row')
        call check(index(err%message, fragment) > 0, what // ': message "' // err%message // &
                   '" says "' // fragment // '"')
    end subroutine decode_expect_error

    subroutine test_decode_report_example3()
        type(tape_t) :: tape
        type(error_t), allocatable :: err
        integer, allocatable :: rows(:)
        rows = example3_rows()
        call check_int(size(rows), 77, 'Example 3 tape length')
        call decode_tape(rows, 'auto', tape, err)
        call check(.not. allocated(err), 'Example 3 decodes')
        call check_int(tape%nframes, 2, 'Example 3 frames')
        call check_str(tape%code, '8', 'Example 3 code')
        call check(tape%told, 'the plain 3 of K13 tells code 8')
        call check(tape%frames(1)%x == 2000 .and. tape%frames(1)%dx == -2000 .and. &
                   tape%frames(1)%dy == -2000 .and. tape%frames(1)%k == 13, 'Example 3 arc frame')
        call check_int(tape%frames(1)%row, 22, 'first frame starts at row 22')
        call check_int(tape%frames(2)%rows(6), 53, 'K of the second frame at row 53')
    end subroutine test_decode_report_example3

    subroutine test_codes_round_trip()
        type(frame_t) :: frames(3)
        integer, allocatable :: rows(:)
        type(tape_t) :: tape
        type(error_t), allocatable :: err
        integer :: i
        ! Example 5, the saw, with a return: digits 3 and 9 tell the variants apart.
        frames(1) = fr(0, 0, 300, 400, 8, 10)
        frames(2) = fr(0, 0, 100, -400, 0, 10)
        frames(3) = fr(0, 0, -3200, 0, 0, 20)
        call encode_tape(frames, 'K', 20, rows, err)
        call check(.not. allocated(err), 'encode the saw in code K')
        call check(any(rows == int(o'23')) .and. .not. any(rows == 3), &
                   'code K punches digit 3 as 23')
        call decode_tape(rows, 'auto', tape, err)
        call check(.not. allocated(err), 'decode the K saw')
        call check(tape%code == 'K' .and. tape%told, 'auto finds code K')
        call check_int(tape%nframes, 3, 'K saw frames')
        do i = 1, 3
            call check(tape%frames(i)%dx == frames(i)%dx .and. tape%frames(i)%dy == frames(i)%dy &
                       .and. tape%frames(i)%cyc == frames(i)%cyc .and. &
                       tape%frames(i)%k == frames(i)%k, 'K saw frame round trip')
        end do
        call decode_expect_error(rows, '8', 23, 'not valid in code 8', 'a K tape read as code 8')
        call encode_tape(frames, '8', 20, rows, err)
        call check(any(rows == 3) .and. .not. any(rows == int(o'23')), 'code 8 punches 3 as 03')
        call decode_tape(rows, 'auto', tape, err)
        call check(.not. allocated(err) .and. tape%code == '8' .and. tape%told, 'auto finds code 8')
        call decode_expect_error(rows, 'K', 23, 'parity error', 'a plain 3 on a controlled tape')
        ! A bad frame is refused by the encoder.
        frames(1) = fr(0, 0, 300, 400, 8, 12)
        call encode_tape(frames, '8', 20, rows, err)
        call check(allocated(err), 'encoder refuses K12')
    end subroutine test_codes_round_trip

    subroutine test_decode_errors()
        integer, allocatable :: r(:), b(:)
        integer, parameter :: GM = int(o'37'), X = int(o'12'), DX = int(o'20'), DY = int(o'21'), &
                              CYC = int(o'30'), K = int(o'16'), KK = int(o'17'), MINUS = int(o'14')
        b = [0, 0, GM]
        call decode_expect_error([integer ::], 'auto', 1, 'tape is empty', 'empty tape')
        call decode_expect_error([0, 0], 'auto', 3, 'missing GM at the start', 'blank tape')
        call decode_expect_error([0, 5, GM], 'auto', 2, 'data before the opening GM', 'leader data')
        r = [b, DX, 5, K, 1, 0, KK]
        call decode_expect_error(r, 'auto', 10, 'missing GM at the end', 'no closing GM')
        call decode_expect_error([b, DX, 5, K, 1, 0, KK, GM, 0, 1], 'auto', 12, 'data after', &
                                 'trailer data')
        call decode_expect_error([b, 64, GM], 'auto', 4, 'not a 5-track row', 'byte over 31')
        call decode_expect_error([b, 27, GM], 'auto', 4, 'not an EM-703 code', 'row outside the code')
        call decode_expect_error([b, 5, K, 1, 0, KK, GM], 'auto', 4, 'at the start of a frame', &
                                 'a digit out of place')
        call decode_expect_error([b, DX, 0, 5, K, 1, 0, KK, GM], 'auto', 5, 'leading zero', &
                                 'leading zero')
        call decode_expect_error([b, DX, 0, K, 1, 0, KK, GM], 'auto', 5, 'zero value', 'a zero DX')
        call decode_expect_error([b, DY, 5, DX, 5, K, 1, 0, KK, GM], 'auto', 6, 'expected digit, CYC or K', &
                                 'DX after DY')
        call decode_expect_error([b, DX, MINUS, K, 1, 0, KK, GM], 'auto', 6, 'expected digit after DX-', &
                                 'minus without digits')
        call decode_expect_error([b, DX, 5, K, 1, 2, KK, GM], 'auto', 6, 'K 12 is not a command', &
                                 'K outside 10/20/11/13')
        call decode_expect_error([b, DX, 5, K, 1, KK, GM], 'auto', 8, 'exactly two digits', 'K with one digit')
        call decode_expect_error([b, DX, 5, K, 1, 0, 1, KK, GM], 'auto', 9, 'exactly two digits', &
                                 'K with three digits')
        call decode_expect_error([b, DX, 5, K, 2, 0, DX, GM], 'auto', 9, 'expected KK', 'no KK')
        call decode_expect_error([b, X, 5, DX, 5, K, 1, 0, KK, GM], 'auto', 4, 'X/Y only with K11/K13', &
                                 'X on a line')
        call decode_expect_error([b, K, 1, 1, KK, GM], 'auto', 4, 'needs X or Y', 'circle without radius')
        ! arc end off its circle: X300 DX-300 DY-310 K13 (end radius 310)
        call decode_expect_error([b, X, 3, 0, 0, DX, MINUS, 3, 0, 0, DY, MINUS, 3, 1, 0, K, 1, 3, KK, &
                                 GM], 'auto', 8, 'not on the circle', 'arc end off its circle')
        ! X1000001: radius over 10 m
        call decode_expect_error([b, X, 1, 0, 0, 0, 0, 0, 1, K, 1, 1, KK, GM], 'auto', 4, &
                                 'exceeds 1000000', 'radius over 10 m')
        call decode_expect_error([b, DX, 5, CYC, 1, K, 1, 0, KK, GM], 'auto', 6, 'at least 2 times', 'CYC1')
        call decode_expect_error([b, DX, 5, CYC, 2, K, 1, 0, KK, GM], 'auto', 6, 'CYC on the last frame', &
                                 'CYC on the last frame')
        call decode_expect_error([b, DX, 5, CYC, 2, K, 1, 0, KK, DX, 5, CYC, 2, K, 1, 0, KK, &
                                 DX, 5, K, 1, 0, KK, GM], 'auto', 14, 'second frame of a cycle pair', &
                                 'CYC on both frames of a pair')
        ! mixed code: a controlled 23 after a plain 3
        call decode_expect_error([b, DX, 3, K, 1, 0, KK, DX, int(o'23'), K, 1, 0, KK, GM], 'auto', 11, &
                                 'mixed code', 'mixed code')
        call decode_expect_error([b, DX, 1, 2, 3, 4, 5, 6, 7, 8, 9, 1, K, 1, 0, KK, GM], 'auto', 14, &
                                 'more than 9 digits', 'ten digits')
    end subroutine test_decode_errors

    subroutine test_frame_text()
        type(text_t) :: text
        type(frame_t) :: frames(2)
        frames(1) = fr(0, 0, 300, 400, 8, 10)
        frames(2) = fr(2000, 0, -2000, -2000, 0, 13)
        call check_str(frame_text(frames(1), .false.), 'DX300 DY400 CYC8 K10 KK', 'frame text')
        call check_str(frame_text(frames(2), .false.), 'X2000 DX-2000 DY-2000 K13 KK', 'arc text')
        call check_str(frame_text(frames(1), .true.), char(206) // char(148) // 'X300 ' // &
            char(206) // char(148) // 'Y400 ' // char(208) // char(166) // '8 ' // &
            char(208) // char(154) // '10 ' // repeat(char(208) // char(154), 2), 'utf8 text')
        call tape_text(frames, .false., text)
        call check_str(text%value(), 'GM' // achar(10) // 'DX300 DY400 CYC8 K10 KK' // achar(10) // &
            'X2000 DX-2000 DY-2000 K13 KK' // achar(10) // 'GM' // achar(10), 'tape text')
    end subroutine test_frame_text

    subroutine test_on_circle()
        call check(on_circle(2000_int64, 0_int64, -2000_int64, -2000_int64), 'quarter arc is on its circle')
        call check(on_circle(300_int64, 0_int64, -601_int64, 0_int64), 'one unit off is within tolerance')
        call check(.not. on_circle(300_int64, 0_int64, -602_int64, 0_int64), 'two units off is not')
        call check(on_circle(300_int64, 0_int64, -300_int64, 301_int64), 'end radius 300.0017 is within')
        call check(on_circle(1000000_int64, 0_int64, -2000000_int64, 0_int64), 'a 10 m half circle')
        call check(.not. on_circle(1000000_int64, 0_int64, 999999999_int64, 0_int64), 'far off, no overflow')
    end subroutine test_on_circle

    subroutine test_sim_saw_cycle()
        type(frame_t) :: frames(3)
        type(run_t) :: run
        type(error_t), allocatable :: err
        type(seg_t), allocatable :: segs(:)
        integer :: n
        real(real64) :: tooth
        frames(1) = fr(0, 0, 300, 400, 8, 10)
        frames(2) = fr(0, 0, 100, -400, 0, 10)
        frames(3) = fr(0, 0, -3200, 0, 0, 20)
        call simulate(frames, run, err)
        call check(.not. allocated(err), 'saw runs')
        call check_int(int(run%executed), 17, 'CYC8 runs the pair 8 times, then the return')
        call run_segments(run, segs, n)
        call check_int(n, 17, 'one segment per executed frame')
        call check(segs(15)%kind == SEG_LINE .and. segs(15)%x0 == 2800 .and. &
                   segs(16)%x1 == 3200 .and. segs(16)%y1 == 0, 'the eighth tooth')
        call check(segs(15)%frame == 1 .and. segs(16)%frame == 2 .and. segs(17)%frame == 3, &
                   'each segment names its frame')
        call check(segs(17)%kind == SEG_TRAVEL, 'the return is travel')
        call check(run%end_x == 0 .and. run%end_y == 0 .and. .not. run%down, 'ends raised at the start')
        tooth = 5.0_real64 + hypot(1.0_real64, 4.0_real64)
        call check(abs(run%drawn_mm - 8 * tooth) < 1e-9_real64, 'saw drawn length')
        call check(abs(run%travel_mm - 32) < 1e-9_real64, 'saw travel')
        call check(abs(run%minutes - (8 * tooth + 32) / 5500) < 1e-12_real64, 'saw minutes')
        call check(run%xmax == 32 .and. run%ymax == 4 .and. run%xmin == 0 .and. run%ymin == 0, 'saw box')
    end subroutine test_sim_saw_cycle

    subroutine test_sim_arcs_and_circles()
        type(frame_t) :: f(1), g(2)
        type(run_t) :: run
        type(error_t), allocatable :: err
        type(seg_t), allocatable :: segs(:)
        integer :: n
        ! Example 3: X2000 DX-2000 DY-2000 K13, clockwise quarter about (-20, 0) mm.
        f(1) = fr(2000, 0, -2000, -2000, 0, 13)
        call simulate(f, run, err)
        call run_segments(run, segs, n)
        call check(segs(1)%kind == SEG_ARC .and. segs(1)%cx == -2000 .and. &
                   segs(1)%cy == 0, 'Example 3 centre')
        call check(abs(segs(1)%sweep + PI / 2) < 1e-12_real64, 'Example 3 sweeps -90 degrees')
        call check(abs(run%drawn_mm - 10 * PI) < 1e-9_real64, 'Example 3 length')
        call check(abs(run%minutes - 10 * PI / 1500) < 1e-12_real64, 'arcs at 1.5 m/min')
        call check(run%xmin == -20 .and. run%xmax == 0 .and. run%ymin == -20 .and. run%ymax == 0, &
                   'Example 3 box')
        call check(run%down, 'an arc leaves the tool down')
        ! The other way round (K11) is three quarters.
        f(1)%k = 11
        call simulate(f, run, err)
        call run_segments(run, segs, n)
        call check(abs(segs(1)%sweep - 3 * PI / 2) < 1e-12_real64, 'K11 is the long way')
        call check(abs(run%ymin + 20) < 1e-9_real64 .and. abs(run%xmin + 40) < 1e-9_real64 .and. &
                   abs(run%ymax - 20) < 1e-9_real64, 'K11 box passes the extremes')
        ! Example 2: Y10000 K13, full circle below the tool, then raise.
        g(1) = fr(0, 10000, 0, 0, 0, 13)
        g(2) = fr(0, 0, 0, 0, 0, 20)
        call simulate(g, run, err)
        call run_segments(run, segs, n)
        call check(abs(segs(1)%sweep + 2 * PI) < 1e-12_real64, 'Example 2 full turn clockwise')
        call check(segs(2)%kind == SEG_RAISE .and. .not. run%down, 'K20 alone raises')
        call check(run%xmin == -100 .and. run%xmax == 100 .and. run%ymin == -200 .and. run%ymax == 0, &
                   'Example 2 box')
        call check(abs(run%drawn_mm - 200 * PI) < 1e-9_real64, 'Example 2 length')
    end subroutine test_sim_arcs_and_circles

    subroutine test_sim_dots_and_field()
        type(frame_t) :: f(4)
        type(run_t) :: run
        type(error_t), allocatable :: err
        type(seg_t), allocatable :: segs(:)
        integer :: n
        f(1) = fr(0, 0, 1000, 0, 0, 20)
        f(2) = fr(0, 0, 0, 0, 0, 10)
        f(3) = fr(0, 0, 0, 0, 0, 20)
        f(4) = fr(0, 0, -1000, 0, 0, 20)
        f(1)%row = 22
        f(2)%row = 30
        f(3)%row = 35
        f(4)%row = 39
        call simulate(f, run, err)
        call run_segments(run, segs, n)
        call check(segs(2)%kind == SEG_DOT .and. segs(2)%x0 == 1000, 'K10 alone is a dot')
        call check(abs(run%drawn_mm) < 1e-12_real64 .and. abs(run%travel_mm - 20) < 1e-9_real64, &
                   'a dot draws no length')
        call field_check(run, 0_int64, 0_int64, 1, 1, err)
        call check(.not. allocated(err), 'on the field from (0, 0)')
        call field_check(run, 119500_int64, 0_int64, 1, 1, err)
        call check(allocated(err), 'leaves the field 5 mm from its edge')
        if (allocated(err)) call check_int(err%number, 22, 'the row of the frame that leaves')
        call field_check(run, 119500_int64, 0_int64, 1, 2, err)
        call check(.not. allocated(err), 'fits at 1:2')
        call field_check(run, 110000_int64, 0_int64, 100, 1, err)
        call check(allocated(err), 'does not fit at 100:1')
    end subroutine test_sim_dots_and_field

    !> A cycle pair is counted, not unrolled: a saw of 999 999 999 teeth runs
    !> at once, and the first pass of a cycle that leaves the field is the
    !> one a frame-by-frame walk finds.
    subroutine test_sim_cycles_are_not_unrolled()
        type(frame_t) :: f(3)
        type(run_t) :: run
        type(error_t), allocatable :: err
        type(seg_t), allocatable :: segs(:)
        real(real64) :: box(4)
        integer :: n, i, first
        f(1) = fr(0, 0, 300, 400, 999999999, 10)
        f(2) = fr(0, 0, 100, -400, 0, 10)
        f(3) = fr(0, 0, 0, 0, 0, 20)
        f(3)%dx = -400 * 999999999_int64
        f(1)%row = 22
        f(2)%row = 30
        f(3)%row = 38
        call simulate(f, run, err)
        call check(.not. allocated(err), 'a saw of 999999999 teeth runs')
        call check(run%executed == 2 * 999999999_int64 + 1, 'every pass counted')
        call check(run%end_x == 0 .and. run%end_y == 0, 'and it comes home')
        call check(abs(run%xmax - 3999999996.0_real64) < 1e-3_real64, 'its box reaches the last tooth')
        call check(abs(run%drawn_mm / 999999999 - (5 + hypot(1.0_real64, 4.0_real64))) < 1e-9_real64, &
                   'drawn length is the teeth')
        ! 500 teeth: the tool passes x = 1200 mm in the 301st tooth's first line
        f(1)%cyc = 500
        f(3)%dx = -400 * 500
        call simulate(f, run, err)
        call field_check(run, 0_int64, 0_int64, 1, 1, err)
        call check(allocated(err), 'a 2000 mm saw leaves the field')
        if (allocated(err)) then
            call check_int(err%number, 22, 'at the row of the cycle''s first frame')
            call check(index(err%message, 'frame 1 ') == 1 .and. &
                       index(err%message, 'x = 1203.00 mm') > 0, 'in its 301st pass: ' // err%message)
        end if
        ! the same pass found by walking every segment
        call run_segments(run, segs, n)
        first = 0
        do i = 1, n
            call seg_box(segs(i), box)
            if (box(2) > 120000 + 1e-6_real64) then
                first = i
                exit
            end if
        end do
        call check_int(first, 601, 'the walk finds the 301st pass''s first line')
        call field_check(run, 0_int64, 0_int64, 1, 2, err)
        call check(.not. allocated(err), 'the saw fits at 1:2')
    end subroutine test_sim_cycles_are_not_unrolled

    subroutine test_svg()
        type(frame_t) :: f(3)
        type(run_t) :: run
        type(error_t), allocatable :: err
        type(text_t) :: svg
        character(len=:), allocatable :: s
        f(1) = fr(2000, 0, -2000, -2000, 0, 13)
        f(2) = fr(-300, 0, 0, 0, 0, 11)
        f(3) = fr(0, 0, 2000, 2000, 0, 20)
        call simulate(f, run, err)
        call svg_run(run, 50_int64, 'test <1>', svg)
        s = svg%value()
        call check(index(s, '<svg xmlns="http://www.w3.org/2000/svg"') > 0, 'svg root')
        call check(index(s, 'test &lt;1&gt;') > 0, 'title escaped')
        call check(index(s, '<path d="M 0.00 0.00 A 20.0000 20.0000 0 0 1 -20.00 20.00"/>') > 0, &
                   'clockwise quarter: sweep flag 1 (y is negated)')
        call check(index(s, '<circle cx="-17.00" cy="20.00" r="3.0000"/>') > 0, 'full circle')
        call check(index(s, 'stroke-width="0.50"') > 0, 'tool width')
        call check(index(s, '<line x1="-20.00" y1="20.00" x2="0.00" y2="0.00"/>') > 0, 'travel line')
        call check(index(s, 'stroke-dasharray') > 0, 'travel dashed')
        call check(s(len(s) - 6:) == '</svg>' // achar(10), 'svg closed')
    end subroutine test_svg

    !> The page of a job: the job's data, each tape's frames (seven numbers a
    !> frame, the last the rows since the previous frame's first row) and rows
    !> (base-32 letters), names escaped for JSON inside a <script> element.
    subroutine test_html()
        type(frame_t) :: f(3)
        type(run_t) :: runs(3)
        type(job_t) :: job
        type(error_t), allocatable :: err
        type(text_t) :: page
        integer, allocatable :: rows(:)
        character(len=:), allocatable :: s, bytes
        integer :: l, i
        f(1) = fr(0, 0, 300, 400, 8, 10)
        f(2) = fr(0, 0, 100, -400, 0, 10)
        f(3) = fr(0, 0, -3200, 0, 0, 20)
        job%name = 'SAW<1>'
        job%title = 'a "saw"'
        job%code = '8'
        job%start_x = 1000
        job%start_y = 2050
        do l = 1, 3
            job%layers(l)%key = trim(merge('small', 'large', l == 1))
            if (l == 3) job%layers(l)%key = 'cond'
            job%layers(l)%tape = 'SAW-' // job%layers(l)%key // '.ptp'
            job%layers(l)%tool = 40
            if (l == 1) then
                call encode_tape(f, '8', 20, rows, err)
            else
                call encode_tape(f(1:0), '8', 20, rows, err)
            end if
            allocate(character(len=size(rows)) :: bytes)
            do i = 1, size(rows)
                bytes(i:i) = achar(rows(i))
            end do
            call simulate_image(bytes, '8', runs(l), err)
            call check(.not. allocated(err), 'html: the tape decodes')
        end do
        call html_job(job, runs, page)
        s = page%value()
        call check(s(1:15) == '<!DOCTYPE html>', 'html: the page starts with its doctype')
        call check(index(s, '<title>EM-703 job SAW&lt;1&gt;</title>') > 0, 'html: title escaped')
        call check(index(s, '{"name":"SAW\u003c1>","job":"a \"saw\"","code":"8","scale":"1:1",' // &
            '"start":["10.00","20.50"],"tapes":["small","large","cond"]}') > 0, 'html: the job')
        call check(index(s, '"gm":[21,59],"frames":3,"executed":17,') > 0, 'html: GM rows, counts')
        call check(index(s, '"f":[0,0,300,400,8,10,1,0,0,100,-400,0,10,14,0,0,-3200,0,0,20,13]') > 0, &
                   'html: the frames, seven numbers each')
        call check(index(s, '"r":"' // repeat('0', 20) // 'vg300h400o8e10fg100hc400e10fgc3200e20fv' &
                   // repeat('0', 20) // '"}') > 0, &
                   'html: the rows in base 32')
        call check(index(s, '"gm":[21,22],"frames":0,"executed":0,') > 0, 'html: an empty tape')
        call check(s(len(s) - 7:) == '</html>' // achar(10), 'html: the page is closed')
        call check(json_string('a<"\' // achar(10)) == '"a\u003c\"\\\u000a"', 'json_string')
    end subroutine test_html

    subroutine test_gcode()
        type(frame_t) :: f(5)
        type(run_t) :: run(1)
        type(error_t), allocatable :: err
        type(text_t) :: g
        character(len=:), allocatable :: s
        integer(int64) :: tools(1)
        f(1) = fr(0, 0, 500, 0, 0, 20)
        f(2) = fr(2000, 0, -2000, -2000, 0, 13)
        f(3) = fr(0, 0, 0, 100, 0, 10)
        f(4) = fr(-300, 0, 0, 0, 0, 11)
        f(5) = fr(0, 0, 1500, 1900, 0, 20)
        call simulate(f, run(1), err)
        tools = 50
        call gcode_program(run, ['tape T'], tools, 'test', 0.0_real64, .false., g)
        s = g%value()
        call check(s(1:2) == '%' // achar(10), 'program starts with %')
        call check(index(s, 'N1 G21 G90 G17 G94') > 0, 'units and modes')
        call check(index(s, 'N3 G00 X5.000 Y0.000' // achar(10) // 'N4 M03' // achar(10) // &
            'N5 G02 X-15.000 Y-20.000 I-20.000 J0.000 F1500') > 0, 'travel, tool down, clockwise arc')
        call check(index(s, 'G01 X-15.000 Y-19.000 F5500') > 0, 'line with its feed')
        call check(index(s, 'G03 X-15.000 Y-19.000 I3.000 J0.000 F1500') > 0, 'full circle G03')
        call check(index(s, 'N8 M05' // achar(10) // 'N9 G00 X0.000 Y0.000') > 0, 'tool up, home')
        call check(index(s, 'M02' // achar(10) // '%' // achar(10)) > 0, 'M02 and %')
        call check(index(s, '(tape T, tool 0.50 mm)') > 0, 'tape comment')
        call g%put('')
        g%n = 0
        call gcode_program(run, ['tape T'], tools, 'test', 0.0_real64, .true., g)
        s = g%value()
        call check(index(s, 'G01 Z0.000 F5500') > 0 .and. index(s, 'G00 Z1.000') > 0 .and. &
                   index(s, 'M03') == 0, '--z: Z moves instead of M03/M05')
    end subroutine test_gcode

    subroutine test_gcode_chords()
        type(frame_t) :: f(1)
        type(run_t) :: run(1)
        type(error_t), allocatable :: err
        type(text_t) :: g
        character(len=:), allocatable :: s
        integer(int64) :: tools(1)
        integer :: n, i, j, count
        real(real64) :: x, y, px, py, worst, d, t, mx, my, r
        ! seed 002: step angle 2 arccos(1 - tol/R); R = 20 mm, tol = 0.01 mm
        n = chord_count(20.0_real64, PI / 2, 0.01_real64)
        t = 2 * acos(1 - (0.01_real64 - ROUNDING) / 20)
        call check_int(n, ceiling(PI / 2 / t), 'chord count from the step angle')
        call check(20 * (1 - cos(PI / 2 / n / 2)) <= 0.01_real64 - ROUNDING, 'sagitta within tol')
        f(1) = fr(2000, 0, -2000, -2000, 0, 13)
        call simulate(f, run(1), err)
        tools = 0
        call gcode_program(run, ['tape T'], tools, 'test', 0.01_real64, .false., g)
        s = g%value()
        call check(index(s, 'G02') == 0, 'no arcs with --chords')
        ! every chord's ends and middle within 0.01 mm of the circle about (-20, 0)
        px = 0
        py = 0
        worst = 0
        count = 0
        i = 1
        do while (i < len(s))
            j = index(s(i:), achar(10)) + i - 1
            if (index(s(i:j), 'G01 X') > 0) then
                read(s(index(s(i:j), 'X') + i:index(s(i:j), ' Y') + i - 2), *) x
                read(s(index(s(i:j), 'Y') + i:j - 1), *) y
                mx = (x + px) / 2
                my = (y + py) / 2
                r = hypot(mx + 20, my)
                d = max(abs(hypot(x + 20, y) - 20), abs(r - 20))
                worst = max(worst, d)
                px = x
                py = y
                count = count + 1
            end if
            i = j + 1
        end do
        call check_int(count, n, 'one G01 per chord')
        call check(worst <= 0.01_real64, 'chords within 0.01 mm: worst ' // fixed(worst, 5))
        call check(abs(px + 20) < 1e-9_real64 .and. abs(py + 20) < 1e-9_real64, 'last chord ends at the end')
    end subroutine test_gcode_chords

    subroutine test_gerber()
        type(frame_t) :: f(5)
        type(run_t) :: run(2)
        type(error_t), allocatable :: err
        type(text_t) :: g
        character(len=:), allocatable :: s
        integer(int64) :: tools(2)
        f(1) = fr(0, 0, 500, 0, 0, 20)
        f(2) = fr(0, 0, 0, 0, 0, 10)
        f(3) = fr(0, 0, 0, 0, 0, 20)
        f(4) = fr(0, 0, -500, 0, 0, 20)
        call simulate(f(1:4), run(1), err)
        f(1) = fr(-300, 0, 0, 0, 0, 11)
        f(2) = fr(2000, 0, -2000, -2000, 0, 13)
        f(3) = fr(0, 0, 2000, 2000, 0, 20)
        call simulate(f(1:3), run(2), err)
        tools = [40_int64, 150_int64]
        call gerber_image(run, ['tape A', 'tape B'], tools, 'test', g)
        s = g%value()
        call check(index(s, '%FSLAX66Y66*%' // achar(10) // '%MOMM*%') > 0, 'format and units')
        call check(index(s, '%ADD10C,0.4000*%') > 0 .and. index(s, '%ADD11C,1.5000*%') > 0, &
                   'one aperture per tape')
        call check(index(s, 'D10*' // achar(10) // 'X0Y0D02*' // achar(10) // 'X5000000Y0D02*' // &
                   achar(10) // 'X5000000Y0D03*') > 0, 'a dot is a flash')
        call check(index(s, 'G03*' // achar(10) // 'X6000000Y0I3000000J0D01*' // achar(10) // &
                   'X0Y0I-3000000J0D01*') > 0, 'a full circle is two half arcs')
        call check(index(s, 'G02*' // achar(10) // 'X-20000000Y-20000000I-20000000J0D01*') > 0, &
                   'clockwise arc in G02 with I J')
        call check(index(s, 'G75*') > 0 .and. s(len(s) - 4:) == 'M02*' // achar(10), 'G75 and M02')
    end subroutine test_gerber

    subroutine test_punch_iso()
        integer, allocatable :: rows(:)
        type(error_t), allocatable :: err
        integer :: i
        call punch_text('%' // achar(10) // 'N1 G01 X-1.5' // achar(13) // achar(10), 'iso', rows, err)
        call check(.not. allocated(err), 'ISO punch')
        call check_int(size(rows), 2 * LEADER + 15, 'ISO rows: leader, 15 characters, trailer (CR dropped)')
        call check_int(rows(LEADER + 1), int(z'A5'), '% (3 holes) gets track 8')
        call check_int(rows(LEADER + 2), 10, 'LF is the end of block, 2 holes')
        call check_int(rows(LEADER + 3), int(z'4E'), 'N has 4 holes, no parity hole')
        call check_int(rows(LEADER + 4), int(z'B1'), '1 (3 holes) gets track 8')
        do i = 1, size(rows)
            call check(mod(popcnt(rows(i)), 2) == 0, 'every ISO row has even parity')
        end do
        call check_str(iso_meaning(int(z'47')), 'G', 'ISO G (4 holes)')
        call check_str(iso_meaning(int(z'C3')), 'C', 'ISO C (3 holes and track 8)')
        call check(index(iso_meaning(int(z'C7')), 'parity') > 0, 'ISO parity error')
        call punch_text('G01' // achar(10) // 'X' // char(200), 'iso', rows, err)
        call check(allocated(err), 'ISO refuses a byte over 127')
        if (allocated(err)) call check_str(error_text(err), 'line 2, column 2: byte 310 (octal) is ' // &
            'not a character of the ISO code (ASCII letters, digits, signs, tab, newline)', &
            'ISO error names line and column')
    end subroutine test_punch_iso

    subroutine test_punch_eia()
        integer, allocatable :: rows(:)
        type(error_t), allocatable :: err
        integer :: i, c
        ! seed 004: digits 8-4-2-1 on tracks 4-3-2-1, track 5 makes the count odd
        call check_int(eia_row(iachar('0')), 32, 'EIA 0 is track 6')
        call check_int(eia_row(iachar('3')), 1 + 2 + 16, 'EIA 3 is 1-2-5')
        call check_int(eia_row(iachar('7')), 7, 'EIA 7 is 1-2-3')
        call check_int(eia_row(iachar('g')), 1 + 2 + 4 + 32 + 64, 'EIA g is 7 with tracks 6, 7')
        call check_int(eia_row(iachar('G')), eia_row(iachar('g')), 'EIA has one case')
        call check_int(eia_row(iachar('x')), 7 + 16 + 32, 'EIA x is 7 with tracks 6 and 5')
        call check_int(eia_row(iachar('m')), 4 + 16 + 64, 'EIA m is 4 with tracks 7 and 5')
        call check_int(eia_row(10), 128, 'EIA end of block is track 8')
        call check_int(eia_row(iachar('#')), -1, 'EIA has no #')
        do c = 32, 122
            if (eia_row(c) > 0) call check(mod(popcnt(eia_row(c)), 2) == 1, &
                'every EIA character has odd parity: ' // achar(c))
        end do
        do c = iachar('a'), iachar('z')
            do i = iachar('0'), iachar('z')
                if (i == c .or. (i >= iachar('A') .and. i <= iachar('Z'))) cycle
                if (eia_row(i) == eia_row(c)) call check(.false., 'EIA codes differ: ' // achar(c) &
                    // ' ' // achar(i))
            end do
        end do
        call punch_text('N10 G01 X-2.5' // achar(10), 'eia', rows, err)
        call check(.not. allocated(err), 'EIA punch')
        call check_int(rows(size(rows) - LEADER), 128, 'EIA block ends with track 8')
        call check_str(eia_meaning(eia_row(iachar('x'))), 'X', 'EIA meaning of x')
        call check_str(eia_meaning(eia_row(iachar('%'))), '% (rewind stop)', 'EIA rewind stop')
        call check(index(eia_meaning(1 + 2), 'parity') > 0, 'EIA parity error')
        call punch_text('G01 X1' // achar(10) // 'G00 #1=2', 'eia', rows, err)
        call check(allocated(err), 'EIA refuses #')
        if (allocated(err)) call check(err%number == 2 .and. err%column == 5, 'EIA error at line 2 column 5')
        ! reading back (eia_char, which eia_meaning uses): every character of
        ! the code, its letters upper case; every other row none
        do c = 0, 127
            i = c
            if (c >= iachar('a') .and. c <= iachar('z')) i = c - 32
            if (eia_row(c) >= 0) call check_int(eia_char(eia_row(c)), i, 'EIA read back: ' // achar(c))
        end do
        do i = 1, 255
            if (any([(eia_row(c) == i, c = 0, 127)])) cycle
            call check_int(eia_char(i), -1, 'EIA row ' // str(i) // ' is no character')
            if (mod(popcnt(i), 2) == 1 .and. i < 128 .and. i /= EIA_DELETE) &
                call check_str(eia_meaning(i), 'not an EIA code', 'EIA row ' // str(i) // ' means none')
        end do
        call check_str(eia_meaning(EIA_DELETE), 'delete', 'EIA delete')
        call check_str(eia_meaning(eia_row(9)), 'tab', 'EIA tab')
        ! the code of a tape: the parity of most punched rows, blank rows aside
        call check_str(iso_or_eia(achar(0) // achar(0) // achar(7) // achar(1) // achar(3)), 'eia', &
            'most rows odd: EIA')
        call check_str(iso_or_eia(achar(3) // achar(1)), 'iso', 'as many even as odd: ISO')
        call check_str(iso_or_eia(''), 'iso', 'no punched row: ISO')
    end subroutine test_punch_eia

    subroutine test_view()
        type(text_t) :: text
        integer, allocatable :: rows(:)
        type(error_t), allocatable :: err
        character(len=:), allocatable :: s
        rows = example3_rows()
        call check_str(guess_code(rows), 'em703', 'a 5-track tape')
        call view_tape(rows, 'em703', 20, 22, text)
        s = text%value()
        call check_str(s, '  row  5 4 3   2 1   code  meaning' // achar(10) // &
            '      +---------------+' // achar(10) // &
            '   20 |      .        | 000   leader' // achar(10) // &
            '   21 |o o o . o o    | 037   GM' // achar(10) // &
            '   22 |  o   . o      | 012   X' // achar(10) // &
            '      +---------------+' // achar(10), 'the picture of docs/TAPE.md')
        call punch_text('G' // achar(10), 'iso', rows, err)
        call check_str(guess_code(rows), 'iso', 'an ISO tape')
        text%n = 0
        call view_tape(rows, 'iso', LEADER + 1, LEADER + 2, text)
        s = text%value()
        call check(index(s, '   21 |  o       . o o o    | 107   G') > 0, 'ISO G: ' // s)
        call check(index(s, '   22 |        o .   o      | 012   end of block (LF)') > 0, 'ISO LF')
        call punch_text('G' // achar(10), 'eia', rows, err)
        call check_str(guess_code(rows), 'eia', 'an EIA tape')
        text%n = 0
        call view_tape(rows, 'eia', LEADER + 2, LEADER + 2, text)
        call check(index(text%value(), '   22 |o' // repeat(' ', 9) // '.' // repeat(' ', 10) // &
                   '| 200   end of block') > 0, 'EIA EOB')
    end subroutine test_view

    subroutine test_jobsheet()
        type(job_t) :: job
        type(error_t), allocatable :: err
        integer :: num, den
        logical :: ok
        call write_text('build/test_em703_tools.job', '# a job sheet' // achar(10) // 'name = T' // &
            achar(10) // 'code = K' // achar(10) // 'scale = 2:1' // achar(10) // &
            'start_x_mm = 100.50' // achar(10) // 'start_y_mm = 7' // achar(10) // &
            'small.tape = T-small.ptp' // achar(10) // 'small.tool_mm = 0.40' // achar(10) // &
            'large.tape = T-large.ptp' // achar(10) // 'large.tool_mm = 1.00' // achar(10) // &
            'cond.tape = T-cond.ptp' // achar(10) // 'cond.tool_mm = 0.5' // achar(10), err)
        call read_job('build/test_em703_tools.job', job, err)
        call check(.not. allocated(err), 'job sheet reads')
        if (allocated(err)) return
        call check(job%name == 'T' .and. job%code == 'K' .and. job%num == 2 .and. job%den == 1, &
                   'name, code, scale')
        call check(job%start_x == 10050 .and. job%start_y == 700, 'start point in units')
        call check_str(job%layers(3)%path, 'build/T-cond.ptp', 'tape beside the job sheet')
        call check(job%layers(1)%tool == 40 .and. job%layers(3)%tool == 50, 'tools in units')
        call write_text('build/test_em703_tools.job', 'name = T' // achar(10) // 'scale 1:1' // achar(10), err)
        call read_job('build/test_em703_tools.job', job, err)
        call check(allocated(err), 'a line without " = " is an error')
        if (allocated(err)) call check_str(error_text(err), 'build/test_em703_tools.job: line 2: ' // &
            'not a "key = value" line: "scale 1:1"', 'job sheet error names the line')
        call parse_scale('1:100', num, den, ok)
        call check(ok .and. machine_scale(num, den), '1:100 is a machine scale')
        call parse_scale('10:1', num, den, ok)
        call check(ok .and. .not. machine_scale(num, den), '10:1 is not in the report''s list')
    end subroutine test_jobsheet

    subroutine test_text_helpers()
        integer(int64) :: u
        logical :: ok
        real(real64) :: r
        call check_str(str(0), '0', 'str 0')
        call check_str(str(-1234567890123_int64), '-1234567890123', 'str of a negative int64')
        call check_str(str(-huge(1_int64) - 1), '-9223372036854775808', 'str of the smallest int64')
        call check_str(str(huge(1)), '2147483647', 'str of the largest integer')
        call check_str(fixed(-0.001_real64, 2), '0.00', 'no negative zero')
        call check_str(fixed(2.345_real64, 1), '2.3', 'fixed rounds')
        call check_str(fixed(-1.5_real64, 0), '-2', 'half away from zero')
        call check_str(mm(-5_int64), '-0.05', 'mm of -5 units')
        call check_str(mm(123456_int64), '1234.56', 'mm of 123456 units')
        call check_str(octal(31, 3), '037', 'octal')
        call parse_mm('12.5', u, ok)
        call check(ok .and. u == 1250, 'parse 12.5 mm')
        call parse_mm('-0.05', u, ok)
        call check(ok .and. u == -5, 'parse -0.05 mm')
        call parse_mm('1.234', u, ok)
        call check(.not. ok, 'three decimals refused')
        call parse_mm('1e3', u, ok)
        call check(.not. ok, 'exponent refused')
        call parse_mm('92233720368547757.99', u, ok)
        call check(ok .and. u == 9223372036854775799_int64, 'the largest mm an int64 of units holds')
        call parse_mm('92233720368547758', u, ok)
        call check(.not. ok, 'mm beyond an int64 of units refused')
        call parse_mm('184467440737095517', u, ok)
        call check(.not. ok, 'mm of 2**64 + 84 units refused, not wrapped to 0.84 mm')
        call parse_int('-123456789012345678', u, ok)
        call check(ok .and. u == -123456789012345678_int64, 'parse_int takes 18 digits')
        call parse_int('1234567890123456789', u, ok)
        call check(.not. ok, 'parse_int refuses 19 digits')
        call parse_real('0.005', r, ok)
        call check(ok .and. abs(r - 0.005_real64) < 1e-15_real64, 'parse 0.005')
        call parse_real('1e-3', r, ok)
        call check(.not. ok, 'parse_real refuses exponents')
    end subroutine test_text_helpers

    !> Seed 004's table: 98132, 87647 pulses in 10 frames of at most 9999.
    subroutine test_split_seed004()
        integer(int64), allocatable :: dxs(:), dys(:)
        integer(int64), parameter :: want_x(10) = [9813, 9813, 9814, 9813, 9813, &
                                                   9813, 9813, 9814, 9813, 9813]
        integer(int64), parameter :: want_y(10) = [8765, 8764, 8765, 8765, 8764, &
                                                   8765, 8765, 8765, 8764, 8765]
        call split_move(98132_int64, 87647_int64, 9999_int64, dxs, dys)
        call check(size(dxs) == 10, 'split: the document splits into 10 frames')
        if (size(dxs) == 10) then
            call check(all(dxs == want_x) .and. all(dys == want_y), 'split: the document''s table')
        end if
        call split_move(0_int64, 0_int64, 9999_int64, dxs, dys)
        call check(size(dxs) == 0, 'split: no move, no frame')
        call split_move(-7_int64, 3_int64, 2_int64, dxs, dys)
        call check(sum(dxs) == -7 .and. sum(dys) == 3 .and. all(abs(dxs) <= 2), &
                   'split: a negative move sums back and keeps the limit')
    end subroutine test_split_seed004

    !> Seed 004's equal frames by continued fractions: 98132, 87647 pulses as
    !> 11 frames of 8779, 7841 (7841/8779, a convergent of 87647/98132) and
    !> the last 1563, 1396; the sums exact, every frame within the limit.
    subroutine test_split_equal_seed004()
        integer(int64) :: fx, fy, n, lx, ly
        real(real64) :: dev
        logical :: ok
        call split_equal(98132_int64, 87647_int64, 9999_int64, fx, fy, n, lx, ly, dev, ok)
        call check(ok .and. fx == 8779 .and. fy == 7841 .and. n == 11 .and. lx == 1563 .and. &
                   ly == 1396, 'split --equal: the document''s move')
        call check(n * fx + lx == 98132 .and. n * fy + ly == 87647, 'split --equal: sums exact')
        call check(abs(dev - 8.3603e-5_real64) < 1.0e-8_real64, 'split --equal: the deviation')
        call split_equal(-7_int64, 3_int64, 2_int64, fx, fy, n, lx, ly, dev, ok)
        call check(ok .and. fx == -2 .and. fy == 1 .and. n == 3 .and. lx == -1 .and. ly == 0, &
                   'split --equal: a negative move')
        call split_equal(0_int64, 0_int64, 9999_int64, fx, fy, n, lx, ly, dev, ok)
        call check(ok .and. n == 0 .and. lx == 0 .and. ly == 0, 'split --equal: no move, no frame')
        call split_equal(600_int64, 400_int64, 9999_int64, fx, fy, n, lx, ly, dev, ok)
        call check(ok .and. fx == 600 .and. fy == 400 .and. n == 1 .and. dev == 0, &
                   'split --equal: a move that fits is one frame')
    end subroutine test_split_equal_seed004

    !> Seed 004's block format: the geometric codes (5500 mm/min is F76, 1500
    !> F65, 1.12**99 the document's 75000), the signed six digits, the G
    !> groups of its example block G02 G17 G45 G61 G83 (one of each), a
    !> program of the report's Example 3 arc, and the check's tape errors.
    subroutine test_iso_block_format()
        type(frame_t) :: f(2)
        type(run_t) :: run(1)
        type(error_t), allocatable :: err
        type(text_t) :: g, msgs
        character(len=:), allocatable :: s
        integer :: nerr, nprog, nblocks
        call check_int(geometric_code(5500.0_real64), 76, 'iso: F76 is 5500 mm/min')
        call check_int(geometric_code(1500.0_real64), 65, 'iso: F65 is 1500 mm/min')
        call check_int(geometric_code(75000.0_real64), 98, 'iso: 75000 is past F98 (99 is rapid)')
        call check_str(signed_digits(2310_int64), '+023100', 'iso: 23.10 mm')
        call check_str(signed_digits(-5_int64), '-000050', 'iso: -0.05 mm')
        call check(g_group(2) == 1 .and. g_group(17) == 2 .and. g_group(45) == 3 .and. &
                   g_group(61) == 4 .and. g_group(83) == 5, 'iso: G02 G17 G45 G61 G83, five groups')
        call check(m_group(3) == m_group(5) .and. m_group(6) /= m_group(2) .and. m_group(7) == 0, &
                   'iso: M groups')
        f(1) = fr(0, 0, 0, 0, 0, 20)
        f(2) = fr(2000, 0, -2000, -2000, 0, 13)
        call simulate(f, run(1), err)
        call iso_program(run, ['tape T'], 'test', 0.0_real64, g, err)
        s = g%value()
        call check(.not. allocated(err) .and. index(s, 'N002 G01 Z-001000 F76' // achar(10) // &
            'N003 G02 X-020000 Y-020000 I-020000 J+000000 F65' // achar(10) // &
            'N004 G00 Z+001000') > 0, 'iso: the arc of Example 3')
        call iso_check(s, msgs, nerr, nprog, nblocks)
        call check(nerr == 0 .and. nprog == 1 .and. nblocks == 5, 'iso: the program checks')
        call iso_check('%' // achar(10) // 'N001 G01 G02 X+000100 Y+000000' // achar(10) // &
                       'N002 M03 M04' // achar(10) // '%' // achar(10), msgs, nerr, nprog, nblocks)
        s = msgs%value()
        call check(nerr == 2 .and. index(s, 'block N001 (line 2): ошибка перфоленты') > 0 .and. &
                   index(s, 'block N002 (line 3): ошибка перфоленты (tape error): M03 and M04') > 0, &
                   'iso: two of one group is a tape error')
    end subroutine test_iso_block_format

    !> SHA-256: the standard's test vectors, the padding's edge lengths, every
    !> byte value (the digits are those of sha256sum).
    subroutine test_sha256()
        character(len=768) :: every
        integer :: i
        call check_str(sha256_hex(''), &
            'e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855', 'sha256 of nothing')
        call check_str(sha256_hex('abc'), &
            'ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad', 'sha256 abc')
        call check_str(sha256_hex('abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq'), &
            '248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1', 'sha256 of two blocks')
        call check_str(sha256_hex(repeat('a', 1000000)), &
            'cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0', 'sha256 of a million a')
        call check_str(sha256_hex(repeat('x', 55)), &
            'd5e285683cd4efc02d021a5c62014694958901005d6f71e89e0989fac77e4072', 'sha256 55 bytes: one block')
        call check_str(sha256_hex(repeat('x', 56)), &
            '04c26261370ee7541549d16dee320c723e3fd14671e66a099afe0a377c16888e', 'sha256 56 bytes: two blocks')
        call check_str(sha256_hex(repeat('x', 64)), &
            '7ce100971f64e7001e8fe5a51973ecdfe1ced42befe7ee8d5fd6219506b5393c', 'sha256 64 bytes')
        do i = 0, 767
            every(i + 1:i + 1) = achar(mod(i, 256))
        end do
        call check_str(sha256_hex(every), &
            'f3a25aa93aa2fbba28d79260535bbd6a5eb0fc1c24a8b0f04e12b484c1dfe363', 'sha256 of every byte value')
    end subroutine test_sha256

    !> write_whole: the file is replaced whole; a target in a missing
    !> directory, or a write that fails (/dev/full), fails with the reason.
    subroutine test_whole_files()
        character(len=:), allocatable :: msg
        call write_whole('test_whole.tmpfile', 'first version', msg)
        call check(len(msg) == 0, 'write_whole writes a file')
        call write_whole('test_whole.tmpfile', 'second', msg)
        call check(len(msg) == 0, 'write_whole replaces a file')
        call check_str(taken_back('test_whole.tmpfile', 6), 'second', &
                       'the file holds the new bytes only')
        call write_whole('no/such/dir/file.txt', 'x', msg)
        call check(index(msg, 'No such file') > 0, 'a missing directory: ' // msg)
        call write_whole('/dev/full', 'x', msg)
        call check(index(msg, 'No space') > 0, 'a write that fails is said: ' // msg)
        call check(same_file('fpm.toml', './fpm.toml'), 'same_file: two spellings')
        call check(.not. same_file('fpm.toml', 'README.md'), 'same_file: two files')
    end subroutine test_whole_files

    !> A package's way of writing (TENZOR's dev_close): two files written to
    !> temporary names, their write-out started, then each fsynced and its
    !> size checked, then renamed; a file whose size on disk is not the size
    !> written is refused and its temporary file removed; a device target is
    !> written straight into.
    subroutine test_staged_files()
        character(len=:), allocatable :: tmp1, tmp2, tmp3, msg
        integer :: fd1, fd2, fd3
        logical :: there
        call open_out('test_stage_a.tmpfile', fd1, tmp1, msg)
        call check(len(msg) == 0 .and. len(tmp1) > 0, 'open_out: a temporary file')
        call open_out('test_stage_b.tmpfile', fd2, tmp2, msg)
        call write_out(fd1, 'alpha', msg)
        call write_out(fd2, 'beta!', msg)
        call write_back(fd1)
        call write_back(fd2)
        inquire(file='test_stage_a.tmpfile', exist=there)
        call check(.not. there, 'nothing at the final name before the rename')
        call close_out(fd1, tmp1, 5_c_long_long, msg)
        call check(len(msg) == 0, 'close_out: fsynced, 5 bytes on disk')
        call close_out(fd2, tmp2, 9_c_long_long, msg)
        call check(len(msg) > 0, 'close_out: 5 bytes on disk where 9 were meant is refused')
        inquire(file=tmp2, exist=there)
        call check(.not. there, 'the refused temporary file is removed')
        call commit_file(tmp1, 'test_stage_a.tmpfile', msg)
        call check(len(msg) == 0, 'commit_file renames the staged file')
        call check_str(taken_back('test_stage_a.tmpfile', 5), 'alpha', &
                       'the renamed file holds its bytes')
        call open_out('/dev/null', fd3, tmp3, msg)
        call check(len(msg) == 0 .and. len(tmp3) == 0, 'a device is written straight into')
        call write_out(fd3, 'x', msg)
        call write_back(fd3)
        call close_out(fd3, tmp3, 1_c_long_long, msg)
        call check(len(msg) == 0, 'write_back and close_out on a device')
        call discard_file(tmp3)
    end subroutine test_staged_files

    !> The first n bytes of file path (blank where it is shorter); the file
    !> is removed.
    function taken_back(path, n) result(got)
        character(len=*), intent(in) :: path
        integer, intent(in) :: n
        character(len=n) :: got
        integer :: u, ios
        got = ''
        open(newunit=u, file=path, access='stream', form='unformatted', action='read', &
             iostat=ios)
        if (ios /= 0) return
        read(u, iostat=ios) got
        close(u, status='delete')
    end function taken_back

end program test_em703_tools
