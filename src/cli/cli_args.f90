!> Command-line arguments as strings (shared by the parasol programs).
module cli_args
    use strings, only: string_t
    implicit none
    private
    public :: get_arguments

contains

    !> All command-line arguments, in order, without the program name.
    subroutine get_arguments(args)
        type(string_t), allocatable, intent(out) :: args(:)
        integer :: i, n, length
        n = command_argument_count()
        allocate (args(n))
        do i = 1, n
            call get_command_argument(i, length=length)
            allocate (character(len=length) :: args(i)%s)
            call get_command_argument(i, args(i)%s)
        end do
    end subroutine get_arguments

end module cli_args
