!> One self-contained HTML page that runs the tapes of a job on an animated
!> coordinatograph (em703 html): the page's template (em703_page, written
!> from src/em703/page/ by scripts/html_page.py) around the data of each
!> tape, decoded here, so that the page never decodes a tape itself.
!>
!> The data are JSON in <script type="application/json"> elements: one for
!> the job (id em703-job), one per tape (id em703-tape-KEY, KEY small, large
!> or cond) holding its frames as integers, seven a frame (X, Y, DX, DY,
!> CYC, K, and the rows from the previous frame's first row, or from the
!> opening GM, to this frame's first row), its rows as one letter each (the
!> row's value 0..31 as a digit of base 32, "0"-"9" "a"-"v"), the rows of
!> its two GM, its tool (0.01 mm), code, executed frames and box (mm, from
!> em703_sim). A frame's last row is the row before the next frame's first
!> (or before the closing GM). Everything streams through the output's
!> text_t: a tape of any length takes a bounded buffer.
module em703_html
    use, intrinsic :: iso_fortran_env, only: int64
    use base_text, only: text_t, str, fixed, mm
    use base_error, only: error_t
    use em703_codec, only: frame_t, decoder_t, decoder_start, next_frame
    use em703_sim, only: run_t
    use em703_jobsheet, only: job_t, NLAYERS
    use em703_page, only: PAGE_HEAD, PAGE_BODY, PAGE_TAIL
    implicit none
    private
    public :: html_job, json_string

    character(len=32), parameter :: BASE32 = '0123456789abcdefghijklmnopqrstuv'
    character(len=10), parameter :: LABELS(NLAYERS) = ['small pads', 'large pads', 'conductors']

contains

    !> The page of a job: runs(l) is the tape of job%layers(l), each run
    !> alone from the start point (em703_sim's simulate_image).
    subroutine html_job(job, runs, text)
        type(job_t), intent(in) :: job
        type(run_t), intent(in) :: runs(NLAYERS)
        type(text_t), intent(inout) :: text
        integer :: l
        character(len=:), allocatable :: keys
        call put_lines(PAGE_HEAD, text)
        call text%add('<title>EM-703 job ' // html_text(job%name) // '</title>')
        call put_lines(PAGE_BODY, text)
        keys = ''
        do l = 1, NLAYERS
            if (l > 1) keys = keys // ','
            keys = keys // json_string(job%layers(l)%key)
        end do
        call text%add('<script type="application/json" id="em703-job">')
        call text%add('{"name":' // json_string(job%name) // ',"job":' // json_string(job%title) // &
            ',"code":' // json_string(runs(1)%code) // ',"scale":"' // str(job%num) // ':' // &
            str(job%den) // '","start":["' // mm(job%start_x) // '","' // mm(job%start_y) // &
            '"],"tapes":[' // keys // ']}')
        call text%add('</script>')
        do l = 1, NLAYERS
            call tape_data(job%layers(l)%key, LABELS(l), job%layers(l)%tape, job%layers(l)%tool, &
                           runs(l), text)
        end do
        call put_lines(PAGE_TAIL, text)
    end subroutine html_job

    subroutine put_lines(lines, text)
        character(len=*), intent(in) :: lines(:)
        type(text_t), intent(inout) :: text
        integer :: i
        do i = 1, size(lines)
            call text%add(trim(lines(i)))
        end do
    end subroutine put_lines

    !> One tape's element: the frames (decoded again from the run's bytes, a
    !> frame at a time) and the rows.
    subroutine tape_data(key, label, file, tool, run, text)
        character(len=*), intent(in) :: key, label, file
        integer(int64), intent(in) :: tool
        type(run_t), intent(in) :: run
        type(text_t), intent(inout) :: text
        type(decoder_t) :: dec
        type(frame_t) :: f
        type(error_t), allocatable :: err
        logical :: got, first
        integer :: gm1, gm2, i, prev, n, v
        character(len=4096) :: chunk
        ! the two GM: the first and the last punched rows of a decoded tape
        gm1 = verify(run%bytes, achar(0))
        gm2 = verify(run%bytes, achar(0), back=.true.)
        call text%add('<script type="application/json" id="em703-tape-' // key // '">')
        call text%put('{"key":' // json_string(key) // ',"label":' // json_string(label) // &
            ',"file":' // json_string(file) // ',"tool":' // str(tool) // ',"code":"' // &
            run%code // '","nrows":' // str(run%nrows) // ',"gm":[' // str(gm1) // ',' // &
            str(gm2) // '],"frames":' // str(run%nframes) // ',"executed":' // &
            str(run%executed) // ',"box":[' // fixed(run%xmin, 2) // ',' // fixed(run%xmax, 2) // &
            ',' // fixed(run%ymin, 2) // ',' // fixed(run%ymax, 2) // '],' // achar(10) // '"f":[')
        prev = gm1
        first = .true.
        call decoder_start(dec, run%bytes, run%code, err, run%evidence)
        do while (.not. allocated(err))
            call next_frame(dec, run%bytes, f, got, err)
            if (.not. got) exit
            if (.not. first) call text%put(',')
            first = .false.
            call text%put(str(f%x) // ',' // str(f%y) // ',' // str(f%dx) // ',' // str(f%dy) // &
                ',' // str(f%cyc) // ',' // str(f%k) // ',' // str(f%row - prev))
            prev = f%row
            if (mod(dec%nframes, 16) == 0) call text%put(achar(10))
        end do
        call text%put('],' // achar(10) // '"r":"')
        n = 0
        do i = 1, len(run%bytes)
            v = iand(iachar(run%bytes(i:i)), 31)
            n = n + 1
            chunk(n:n) = BASE32(v + 1:v + 1)
            if (n == len(chunk)) then
                call text%put(chunk)
                n = 0
            end if
        end do
        if (n > 0) call text%put(chunk(1:n))
        call text%add('"}')
        call text%add('</script>')
    end subroutine tape_data

    !> s as a JSON string in a page: quotes, backslashes and control
    !> characters escaped, and "<" as \u003c (no "</script>" can end the
    !> element early). Other bytes pass as they are (the page is UTF-8).
    function json_string(s) result(j)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: j
        character(len=*), parameter :: HEX = '0123456789abcdef'
        integer :: i, c
        j = '"'
        do i = 1, len(s)
            c = iachar(s(i:i))
            select case (c)
            case (34)
                j = j // '\"'
            case (92)
                j = j // '\\'
            case (0:31, 60, 127)
                j = j // '\u00' // HEX(c / 16 + 1:c / 16 + 1) // HEX(mod(c, 16) + 1:mod(c, 16) + 1)
            case default
                j = j // s(i:i)
            end select
        end do
        j = j // '"'
    end function json_string

    !> s as HTML text: & < > escaped.
    function html_text(s) result(h)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: h
        integer :: i
        h = ''
        do i = 1, len(s)
            select case (s(i:i))
            case ('&')
                h = h // '&amp;'
            case ('<')
                h = h // '&lt;'
            case ('>')
                h = h // '&gt;'
            case default
                h = h // s(i:i)
            end select
        end do
    end function html_text

end module em703_html
