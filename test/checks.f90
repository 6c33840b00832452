!> A very small test-suite module: checks count passes and failures, a failure
!> prints what was expected and what came; the main prints 'N passed, N failed'.
module checks
    use, intrinsic :: iso_fortran_env, only: error_unit
    implicit none
    private
    public :: check, check_int, check_str, summary

    integer :: npass = 0, nfail = 0

contains

    subroutine check(ok, what)
        logical, intent(in) :: ok
        character(len=*), intent(in) :: what
        if (ok) then
            npass = npass + 1
        else
            nfail = nfail + 1
            write(error_unit, '(a)') 'FAIL: ' // what
        end if
    end subroutine check

    subroutine check_int(got, want, what)
        integer, intent(in) :: got, want
        character(len=*), intent(in) :: what
        character(len=40) :: g, w
        write(g, '(i0)') got
        write(w, '(i0)') want
        call check(got == want, what // ': got ' // trim(g) // ', want ' // trim(w))
    end subroutine check_int

    subroutine check_str(got, want, what)
        character(len=*), intent(in) :: got, want
        character(len=*), intent(in) :: what
        call check(got == want, what // ': got "' // got // '", want "' // want // '"')
    end subroutine check_str

    !> Print the closing line and return the process status (0 when all passed).
    integer function summary()
        write(*, '(i0, a, i0, a)') npass, ' passed, ', nfail, ' failed'
        summary = merge(0, 1, nfail == 0)
    end function summary

end module checks
