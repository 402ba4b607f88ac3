!> parasol-bench mesh FILE: times reading a mesh (.mail or Gmsh .msh, by extension).
module bench_mesh
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
    use kinds, only: dp
    use status, only: status_t, format_status
    use strings, only: to_text, string_t
    use mesh_types, only: mesh_t
    use mesh_reader, only: read_mesh
    implicit none
    private
    public :: run_bench_mesh
contains
    !> `parasol-bench mesh FILE`: args = [FILE]. Reads FILE once and prints
    !> `RESULT mesh file=F nodes=N cells=C seconds=S`; exit_status 0, or 1 (with the error
    !> or the usage on stderr) if the mesh cannot be read or FILE is missing.
    subroutine run_bench_mesh(args, exit_status)
        type(string_t), intent(in) :: args(:)
        integer, intent(out) :: exit_status
        if (size(args) /= 1) then
            write (error_unit, '(a)') 'parasol-bench mesh: error: give one mesh file; usage: ' // &
                'parasol-bench mesh FILE   (.mail, or .msh for Gmsh)'
            exit_status = 1
            return
        end if
        call time_mesh_read(args(1)%s, exit_status)
    end subroutine run_bench_mesh

    subroutine time_mesh_read(path, exit_status)
        character(len=*), intent(in) :: path
        integer, intent(out) :: exit_status
        type(mesh_t) :: mesh
        type(status_t) :: st
        integer(int64) :: t0, t1, rate
        real(dp) :: seconds
        character(len=12) :: buf
        call system_clock(t0, rate)
        call read_mesh(path, mesh, st)
        call system_clock(t1)
        if (st%failed()) then
            write (error_unit, '(a)') 'parasol-bench mesh: ' // format_status(st)
            exit_status = 1
            return
        end if
        seconds = real(t1 - t0, dp) / real(rate, dp)
        write (buf, '(f12.4)') seconds
        write (output_unit, '(a)') 'RESULT mesh file=' // path // ' nodes=' // &
            to_text(mesh%n_nodes) // ' cells=' // to_text(mesh%n_cells) // ' seconds=' // &
            trim(adjustl(buf))
        exit_status = 0
    end subroutine time_mesh_read
end module bench_mesh
