!> Fortran tests: the number reader and the text helpers of the FORTRAN 77
!> programs (called through explicit interfaces, as the shell calls TENZOR), and
!> the card reader of the device layer.
program test_legacy_monitor
    use checks, only: check, check_int, check_str, summary
    use monitor_devices, only: dev_load_deck, dev_next_card
    implicit none

    interface
        subroutine cmnum(card, ic1, ic2, ndec, ival, lblank, ierr, iecol)
            character(len=*), intent(in) :: card
            integer, intent(in) :: ic1, ic2, ndec
            integer, intent(out) :: ival, lblank, ierr, iecol
        end subroutine cmnum
        subroutine cmitoa(ival, str, lstr)
            integer, intent(in) :: ival
            character(len=*), intent(out) :: str
            integer, intent(out) :: lstr
        end subroutine cmitoa
        subroutine cmfmm(ival, str, lstr)
            integer, intent(in) :: ival
            character(len=*), intent(out) :: str
            integer, intent(out) :: lstr
        end subroutine cmfmm
        subroutine cmfdp(x, str)
            double precision, intent(in) :: x
            character(len=*), intent(out) :: str
        end subroutine cmfdp
    end interface

    call test_cmnum()
    call test_text()
    call test_decimals()
    call test_card_reader()
    if (summary() /= 0) stop 1, quiet=.true.

contains

    !> One F10.2 field in columns 11-20 of an otherwise blank card.
    subroutine field(text, ndec, want_val, want_err, want_col)
        character(len=*), intent(in) :: text
        integer, intent(in) :: ndec, want_val, want_err, want_col
        character(len=80) :: card
        integer :: ival, lblank, ierr, iecol
        card = ' '
        card(11:20) = text
        call cmnum(card, 11, 20, ndec, ival, lblank, ierr, iecol)
        call check_int(ierr, want_err, 'cmnum error code of "' // text // '"')
        if (want_err == 0) call check_int(ival, want_val, 'cmnum value of "' // text // '"')
        if (want_err /= 0) call check_int(iecol, want_col, 'cmnum column of "' // text // '"')
    end subroutine field

    subroutine test_cmnum()
        character(len=80) :: card
        integer :: ival, lblank, ierr, iecol
        ! F10.2 without a point: the last two digits are decimals (docs/CARDS.md)
        call field('      1250', 2, 1250, 0, 0)
        call field('     12.50', 2, 1250, 0, 0)
        call field('12.5      ', 2, 1250, 0, 0)
        call field('    -0.05 ', 2, -5, 0, 0)
        call field('       -5.', 2, -500, 0, 0)
        call field('   +3     ', 2, 0, 5, 16)      ! no point and not right-justified
        call field('   1 2.5  ', 2, 0, 2, 15)      ! blank inside
        call field('    1.255 ', 2, 0, 3, 19)      ! a third decimal that is not zero
        call field('    1.250 ', 2, 125, 0, 0)     ! a third decimal that is zero
        call field('   12.5Q  ', 2, 0, 1, 18)
        call field('    1.5E2 ', 2, 0, 1, 18)      ! no exponents on cards
        call field('        - ', 2, 0, 6, 19)
        call field('      1.2.', 2, 0, 1, 20)
        call field('9999999999', 2, 0, 4, 11)      ! more than 999999999 hundredths
        call field('   9999999', 0, 9999999, 0, 0)
        call field('      12.', 0, 0, 7, 19)       ! point in a whole-number field
        card = ' '
        call cmnum(card, 11, 20, 2, ival, lblank, ierr, iecol)
        call check(lblank == 1 .and. ierr == 0 .and. ival == 0, 'a blank field is blank and zero')
    end subroutine test_cmnum

    subroutine test_text()
        character(len=12) :: s
        integer :: l
        call cmitoa(0, s, l)
        call check_str(s(1:l), '0', 'cmitoa 0')
        call cmitoa(-2147483647 - 1, s, l)
        call check_str(s(1:l), '-2147483648', 'cmitoa of the most negative integer')
        call cmfmm(1250, s, l)
        call check_str(s(1:l), '12.50', 'cmfmm 1250')
        call cmfmm(-5, s, l)
        call check_str(s(1:l), '-0.05', 'cmfmm -5')
        call cmfmm(-123456, s, l)
        call check_str(s(1:l), '-1234.56', 'cmfmm -123456')
    end subroutine test_text

    !> CMFDP: the listing's decimals, right-justified, always with the zero
    !> before the point, asterisks when the value does not fit.
    subroutine test_decimals()
        character(len=14) :: s14
        character(len=10) :: s10
        character(len=4) :: s4
        call cmfdp(0.7d0, s10)
        call check_str(s10, '      0.70', 'cmfdp 0.7: the zero before the point')
        call cmfdp(0d0, s10)
        call check_str(s10, '      0.00', 'cmfdp 0')
        call cmfdp(0.004999d0, s10)
        call check_str(s10, '      0.00', 'cmfdp rounds down below a half hundredth')
        call cmfdp(0.005001d0, s10)
        call check_str(s10, '      0.01', 'cmfdp rounds up above a half hundredth')
        call cmfdp(780.87d0, s14)
        call check_str(s14, '        780.87', 'cmfdp 780.87')
        call cmfdp(9999.996d0, s14)
        call check_str(s14, '      10000.00', 'cmfdp carries into the high part')
        call cmfdp(10000.05d0, s14)
        call check_str(s14, '      10000.05', 'cmfdp keeps the zeros of the low part')
        call cmfdp(123456789.25d0, s14)
        call check_str(s14, '  123456789.25', 'cmfdp past the range of a 32-bit hundredth')
        call cmfdp(-1.5d0, s10)
        call check_str(s10, '     -1.50', 'cmfdp negative')
        call cmfdp(-0.001d0, s10)
        call check_str(s10, '      0.00', 'cmfdp: no minus zero')
        call cmfdp(12.5d0, s4)
        call check_str(s4, '****', 'cmfdp: too wide is asterisks')
        call cmfdp(1.0d20, s14)
        call check_str(s14, repeat('*', 14), 'cmfdp: far too wide is asterisks')
    end subroutine test_decimals

    subroutine test_card_reader()
        character(len=*), parameter :: path = 'build/test_deck.crd'
        character(len=80) :: card
        character(len=:), allocatable :: msg
        integer :: u, ncol, iend
        logical :: ok
        open(newunit=u, file=path, access='stream', form='unformatted', status='replace')
        write(u) 'FIRST' // achar(13) // achar(10) // repeat('X', 85) // achar(10) // 'LAST'
        close(u)
        call dev_load_deck(path, ok, msg)
        call check(ok, 'the test deck loads')
        call dev_next_card(card, ncol, iend)
        call check(iend == 0 .and. card == 'FIRST' .and. ncol == 5, 'CR LF ends a card')
        call dev_next_card(card, ncol, iend)
        call check(iend == 0 .and. ncol == 85 .and. card == repeat('X', 80), &
                   'a long line keeps its length and its first 80 columns')
        call dev_next_card(card, ncol, iend)
        call check(iend == 0 .and. card == 'LAST', 'the last line needs no newline')
        call dev_next_card(card, ncol, iend)
        call check_int(iend, 1, 'end of the deck')
        call dev_load_deck('build', ok, msg)
        call check(.not. ok, 'a directory is not a deck')
        open(newunit=u, file=path, status='old')
        close(u, status='delete')
    end subroutine test_card_reader

end program test_legacy_monitor
