!> The version of the programs (tenzor --version, em703 --version): the
!> version of fpm.toml, which a test keeps equal to this one.
module base_version
    implicit none
    private
    character(len=*), parameter, public :: VERSION = '0.1.0'
    character(len=*), parameter, public :: VERSION_LINE_TAIL = &
        ' (EM-703 tape subsystem: JINR P11-10356, 1977, re-created)'
end module base_version
