!> parasol's MUMPS plug-in: MUMPS's Fortran API (Debian libmumps-seq-dev, or libmumps-dev
!> with OpenMPI for the distributed build) behind plain bind(C) entry points, loaded at run
!> time by src/solvers/mumps_solver.f90 (dlopen) so that runs without METHODE='MUMPS' never
!> load MUMPS. One handle = one DMUMPS_STRUC instance (JOB = -1 at create, -2 at destroy).
!>
!> The matrix comes as the upper triangle compressed by columns (1-based); MUMPS takes it as
!> coordinates (IRN, JCN, A) with SYM = 2 (general symmetric, as Code_Aster uses it), kept
!> centralised on the host (ICNTL(18) = 0, ICNTL(5) = 0). Return codes: 0 success, -1 MUMPS
!> error (INFOG(1), INFOG(2) in info), -3 bad argument.
!>
!> Distributed build (PARASOL_MUMPS_MPI): process 0 runs parasol and calls these entry
!> points; before each MUMPS call it broadcasts the job, so that the other processes, which
!> wait in parasol_mumps_worker, take part in the same MUMPS phase on their own instance.
module parasol_mumps_plugin
    use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_f_pointer, c_null_ptr, &
        c_associated, c_int32_t, c_int64_t, c_double
    implicit none
    private
    include 'mpif.h'
    include 'dmumps_struc.h'

    !> One MUMPS instance.
    type :: instance_t
        type(dmumps_struc) :: id
    end type instance_t

    !> Worker commands (broadcast by process 0 in the distributed build).
    integer, parameter :: CMD_STOP = 0, CMD_CREATE = 1, CMD_ANALYSE = 2, CMD_FACTOR = 3, &
        CMD_SOLVE = 4, CMD_DESTROY = 5

    public :: parasol_mumps_create, parasol_mumps_analyse, parasol_mumps_factor, &
        parasol_mumps_solve, parasol_mumps_destroy, parasol_mumps_start, &
        parasol_mumps_stop, parasol_mumps_worker

contains

    !> MPI start (no-op stub in the sequential library): returns this process's rank and the
    !> number of processes.
    function parasol_mumps_start(rank, size) result(rc) bind(c, name='parasol_mumps_start')
        integer(c_int32_t), intent(out) :: rank, size
        integer(c_int32_t) :: rc
        integer :: ierr, r, s
        logical :: started
        call mpi_initialized(started, ierr)
        if (.not. started) call mpi_init(ierr)
        call mpi_comm_rank(MPI_COMM_WORLD, r, ierr)
        call mpi_comm_size(MPI_COMM_WORLD, s, ierr)
        rank = int(r, c_int32_t)
        size = int(s, c_int32_t)
        rc = 0
    end function parasol_mumps_start

    !> Ends the workers (distributed build) and MPI.
    subroutine parasol_mumps_stop() bind(c, name='parasol_mumps_stop')
        integer :: ierr, s
        logical :: started
        call mpi_initialized(started, ierr)
        if (.not. started) return
        call mpi_comm_size(MPI_COMM_WORLD, s, ierr)
        if (s > 1) call broadcast_command(CMD_STOP, 0, 0)
        call mpi_finalize(ierr)
    end subroutine parasol_mumps_stop

    !> Process 0 tells the workers what comes next (command, an integer argument).
    subroutine broadcast_command(cmd, arg1, arg2)
        integer, intent(in) :: cmd, arg1, arg2
        integer :: buf(3), ierr, s
        call mpi_comm_size(MPI_COMM_WORLD, s, ierr)
        if (s <= 1) return
        buf = [cmd, arg1, arg2]
        call mpi_bcast(buf, 3, MPI_INTEGER, 0, MPI_COMM_WORLD, ierr)
    end subroutine broadcast_command

    !> The loop of processes 1..N-1: each command of process 0 is a MUMPS phase on this
    !> process's own instance (one at a time); returns at CMD_STOP.
    subroutine parasol_mumps_worker() bind(c, name='parasol_mumps_worker')
        type(instance_t), pointer :: inst
        integer :: buf(3), ierr
        inst => null()
        do
            call mpi_bcast(buf, 3, MPI_INTEGER, 0, MPI_COMM_WORLD, ierr)
            select case (buf(1))
            case (CMD_STOP)
                exit
            case (CMD_CREATE)
                if (associated(inst)) call end_instance(inst)
                allocate (inst)
                call init_instance(inst, buf(2))
            case (CMD_ANALYSE)
                inst%id%job = 1
                call dmumps(inst%id)
            case (CMD_FACTOR)
                call mpi_bcast(inst%id%icntl, 60, MPI_INTEGER, 0, MPI_COMM_WORLD, ierr)
                call mpi_bcast(inst%id%cntl, 15, MPI_DOUBLE_PRECISION, 0, MPI_COMM_WORLD, ierr)
                inst%id%job = 2
                call dmumps(inst%id)
            case (CMD_SOLVE)
                inst%id%nrhs = buf(2)
                inst%id%job = 3
                call dmumps(inst%id)
            case (CMD_DESTROY)
                if (associated(inst)) call end_instance(inst)
                inst => null()
            end select
        end do
        call mpi_finalize(ierr)
    end subroutine parasol_mumps_worker

    subroutine init_instance(inst, ordering)
        type(instance_t), intent(inout) :: inst
        integer, intent(in) :: ordering
        inst%id%comm = MPI_COMM_WORLD
        inst%id%sym = 2
        inst%id%par = 1
        ! MUMPS's JOB = -1 reads KEEP(40) to detect an instance initialised twice (its driver
        ! says "non initialized value"): a fresh structure gets a value that means "never
        ! initialised" (valgrind: a conditional jump on uninitialised memory otherwise).
        inst%id%keep(40) = 0
        inst%id%job = -1
        call dmumps(inst%id)
        ! no output from MUMPS: parasol writes its own diagnostics
        inst%id%icntl(1:4) = [-1, -1, -1, 0]
        inst%id%icntl(5) = 0        ! assembled matrix
        inst%id%icntl(18) = 0       ! centralised on the host
        inst%id%icntl(28) = 1       ! sequential analysis
        inst%id%icntl(7) = ordering
        inst%id%icntl(8) = 0        ! no scaling: parasol scales to a unit diagonal itself
    end subroutine init_instance

    subroutine end_instance(inst)
        type(instance_t), pointer, intent(inout) :: inst
        inst%id%job = -2
        call dmumps(inst%id)
        if (associated(inst%id%irn)) deallocate (inst%id%irn)
        if (associated(inst%id%jcn)) deallocate (inst%id%jcn)
        if (associated(inst%id%a)) deallocate (inst%id%a)
        if (associated(inst%id%rhs)) deallocate (inst%id%rhs)
        deallocate (inst)
    end subroutine end_instance

    !> A new instance with MUMPS ordering ICNTL(7) = ordering; null on failure.
    function parasol_mumps_create(ordering) result(handle) bind(c, name='parasol_mumps_create')
        integer(c_int32_t), value :: ordering
        type(c_ptr) :: handle
        type(instance_t), pointer :: inst
        integer(c_int32_t) :: r, s
        handle = c_null_ptr
        if (parasol_mumps_start(r, s) /= 0) return
        call broadcast_command(CMD_CREATE, int(ordering), 0)
        allocate (inst)
        call init_instance(inst, int(ordering))
        if (inst%id%infog(1) < 0) return
        handle = c_loc(inst)
    end function parasol_mumps_create

    subroutine parasol_mumps_destroy(handle) bind(c, name='parasol_mumps_destroy')
        type(c_ptr), value :: handle
        type(instance_t), pointer :: inst
        if (.not. c_associated(handle)) return
        call c_f_pointer(handle, inst)
        call broadcast_command(CMD_DESTROY, 0, 0)
        call end_instance(inst)
    end subroutine parasol_mumps_destroy

    !> JOB = 1 on the pattern (upper triangle by columns, 1-based).
    !>  entries : out, estimated entries of the factor (INFOG(20) x 1e6 if negative)
    !>  flops   : out, estimated flops of the elimination (RINFOG(1))
    !>  info    : out, INFOG(1), INFOG(2)
    function parasol_mumps_analyse(handle, n, col_ptr, row_index, entries, flops, info) &
        result(rc) bind(c, name='parasol_mumps_analyse')
        type(c_ptr), value :: handle
        integer(c_int64_t), value :: n
        integer(c_int64_t), intent(in) :: col_ptr(n + 1)
        integer(c_int32_t), intent(in) :: row_index(*)
        integer(c_int64_t), intent(out) :: entries
        real(c_double), intent(out) :: flops
        integer(c_int32_t), intent(out) :: info(2)
        integer(c_int32_t) :: rc
        type(instance_t), pointer :: inst
        integer(c_int64_t) :: j, k
        rc = -3
        entries = 0
        flops = 0.0d0
        info = 0
        if (.not. c_associated(handle) .or. n < 0) return
        call c_f_pointer(handle, inst)
        if (associated(inst%id%irn)) deallocate (inst%id%irn)
        if (associated(inst%id%jcn)) deallocate (inst%id%jcn)
        if (associated(inst%id%a)) deallocate (inst%id%a)
        inst%id%n = int(n)
        inst%id%nnz = col_ptr(n + 1) - 1
        allocate (inst%id%irn(inst%id%nnz), inst%id%jcn(inst%id%nnz), inst%id%a(inst%id%nnz))
        do j = 1, n
            do k = col_ptr(j), col_ptr(j + 1) - 1
                inst%id%irn(k) = row_index(k)
                inst%id%jcn(k) = int(j)
            end do
        end do
        inst%id%a = 0.0d0
        call broadcast_command(CMD_ANALYSE, 0, 0)
        inst%id%job = 1
        call dmumps(inst%id)
        info = [int(inst%id%infog(1), c_int32_t), int(inst%id%infog(2), c_int32_t)]
        rc = 0
        if (inst%id%infog(1) < 0) rc = -1
        entries = int(inst%id%infog(20), c_int64_t)
        if (entries < 0) entries = -entries * 1000000_c_int64_t
        flops = real(inst%id%rinfog(1), c_double)
    end function parasol_mumps_analyse

    !> JOB = 2 with `values` (the analysed pattern's order). detect = 1: null pivots with
    !> |pivot| below cntl3 (MUMPS CNTL(3)) are detected and fixed (CNTL(5) = fixation), and
    !> listed in null_list(1:n_null).
    !>  n_negative : out, INFOG(12), negative pivots
    !>  entries    : out, INFOG(29), entries of the factor
    !>  megabytes  : out, INFOG(22), memory used by the factorization (MB)
    function parasol_mumps_factor(handle, values, detect, cntl3, fixation, n_null, null_list, &
                                  n_negative, entries, megabytes, info) result(rc) &
        bind(c, name='parasol_mumps_factor')
        type(c_ptr), value :: handle
        real(c_double), intent(in) :: values(*)
        integer(c_int32_t), value :: detect
        real(c_double), value :: cntl3, fixation
        integer(c_int64_t), intent(out) :: n_null, n_negative, entries, megabytes
        integer(c_int32_t), intent(inout) :: null_list(*)
        integer(c_int32_t), intent(out) :: info(2)
        integer(c_int32_t) :: rc
        type(instance_t), pointer :: inst
        integer :: ierr
        rc = -3
        n_null = 0
        n_negative = 0
        entries = 0
        megabytes = 0
        info = 0
        if (.not. c_associated(handle)) return
        call c_f_pointer(handle, inst)
        if (.not. associated(inst%id%a)) return
        inst%id%a = values(1:inst%id%nnz)
        inst%id%icntl(24) = int(detect)
        inst%id%icntl(13) = 0
        if (detect == 1) inst%id%icntl(13) = 1
        inst%id%cntl(3) = cntl3
        inst%id%cntl(5) = fixation
        call broadcast_command(CMD_FACTOR, 0, 0)
        if (worker_count() > 0) then
            call mpi_bcast(inst%id%icntl, 60, MPI_INTEGER, 0, MPI_COMM_WORLD, ierr)
            call mpi_bcast(inst%id%cntl, 15, MPI_DOUBLE_PRECISION, 0, MPI_COMM_WORLD, ierr)
        end if
        inst%id%job = 2
        call dmumps(inst%id)
        info = [int(inst%id%infog(1), c_int32_t), int(inst%id%infog(2), c_int32_t)]
        if (inst%id%infog(1) < 0) then
            rc = -1
            return
        end if
        n_null = inst%id%infog(28)
        if (n_null > 0) null_list(1:n_null) = inst%id%pivnul_list(1:n_null)
        n_negative = inst%id%infog(12)
        entries = int(inst%id%infog(29), c_int64_t)
        if (entries < 0) entries = -entries * 1000000_c_int64_t
        megabytes = inst%id%infog(22)
        rc = 0
    end function parasol_mumps_factor

    !> JOB = 3: b (n x nrhs, column-major) <- A^-1 b.
    function parasol_mumps_solve(handle, nrhs, b, info) result(rc) &
        bind(c, name='parasol_mumps_solve')
        type(c_ptr), value :: handle
        integer(c_int64_t), value :: nrhs
        real(c_double), intent(inout) :: b(*)
        integer(c_int32_t), intent(out) :: info(2)
        integer(c_int32_t) :: rc
        type(instance_t), pointer :: inst
        integer(c_int64_t) :: m
        rc = -3
        info = 0
        if (.not. c_associated(handle) .or. nrhs < 0) return
        call c_f_pointer(handle, inst)
        m = int(inst%id%n, c_int64_t) * nrhs
        if (associated(inst%id%rhs)) deallocate (inst%id%rhs)
        allocate (inst%id%rhs(max(1_c_int64_t, m)))
        inst%id%rhs(1:m) = b(1:m)
        inst%id%nrhs = int(nrhs)
        inst%id%lrhs = inst%id%n
        call broadcast_command(CMD_SOLVE, int(nrhs), 0)
        inst%id%job = 3
        call dmumps(inst%id)
        info = [int(inst%id%infog(1), c_int32_t), int(inst%id%infog(2), c_int32_t)]
        if (inst%id%infog(1) < 0) then
            rc = -1
            return
        end if
        b(1:m) = inst%id%rhs(1:m)
        rc = 0
    end function parasol_mumps_solve

    integer function worker_count()
        integer :: s, ierr
        call mpi_comm_size(MPI_COMM_WORLD, s, ierr)
        worker_count = s - 1
    end function worker_count

end module parasol_mumps_plugin
