!> The command line, one argument at a time, whatever its length: the one
!> reader of arguments that both programs (app/tenzor.f90, app/em703.f90) use.
module base_args
    implicit none
    private
    public :: get_arg

contains

    !> Argument k of the command line (0 = the program), as long as it is;
    !> an empty string for an empty argument or one that does not exist.
    function get_arg(k) result(s)
        integer, intent(in) :: k
        character(len=:), allocatable :: s
        integer :: n
        call get_command_argument(k, length=n)
        allocate(character(len=n) :: s)
        if (n > 0) call get_command_argument(k, s)
    end function get_arg

end module base_args
