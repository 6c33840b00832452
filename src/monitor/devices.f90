!> The device routines that the FORTRAN 77 programs in legacy/ call, as plain
!> external subroutines with the argument types of their CALLs there. Each one
!> only hands its arguments to the monitor_devices module.

!> Card reader: the next card; ncol is the length of the line (more than 80 is
!> an error that TENZOR reports), iend = 1 when the deck is exhausted.
subroutine dvcard(card, ncol, iend)
    use monitor_devices, only: dev_next_card
    implicit none
    character(len=80), intent(out) :: card
    integer, intent(out) :: ncol, iend
    call dev_next_card(card, ncol, iend)
end subroutine dvcard

!> Line printer: one line of the package's listing.
subroutine dvprnt(line)
    use monitor_devices, only: dev_print
    implicit none
    character(len=*), intent(in) :: line
    call dev_print(line)
end subroutine dvprnt

!> Operator's console: one error line.
subroutine dverr(line)
    use monitor_devices, only: dev_error
    implicit none
    character(len=*), intent(in) :: line
    call dev_error(line)
end subroutine dverr

!> Begin the output of the package whose file name is name.
subroutine dvopen(name)
    use monitor_devices, only: dev_open
    implicit none
    character(len=*), intent(in) :: name
    call dev_open(name)
end subroutine dvopen

!> Tape punch iu (1 small pads, 2 large pads, 3 conductors): one row.
subroutine dvpnch(iu, irow)
    use monitor_devices, only: dev_punch
    implicit none
    integer, intent(in) :: iu, irow
    call dev_punch(iu, irow)
end subroutine dvpnch

!> One line of the frame text of tape iu.
subroutine dvtext(iu, line)
    use monitor_devices, only: dev_text
    implicit none
    integer, intent(in) :: iu
    character(len=*), intent(in) :: line
    call dev_text(iu, line)
end subroutine dvtext

!> One line of the job sheet.
subroutine dvjob(line)
    use monitor_devices, only: dev_job
    implicit none
    character(len=*), intent(in) :: line
    call dev_job(line)
end subroutine dvjob

!> Close the package: ikeep = 1 keeps its tapes, 0 discards them.
subroutine dvclos(ikeep)
    use monitor_devices, only: dev_close
    implicit none
    integer, intent(in) :: ikeep
    call dev_close(ikeep == 1)
end subroutine dvclos
