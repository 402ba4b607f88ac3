!> The deck evaluator (deck_interpreter), the part of Code_Aster's code_aster.MedUtils that a
!> run of one process gives a meaning to (doc/deck-language.md, "Modules"):
!> splitMeshAndFieldsFromMedFile(filename, ...) reads a MED mesh and its fields split over
!> the MPI processes (a ParallelMesh, MedMeshAndFieldsSplitter.py). parasol runs as one
!> process, whose part is the whole mesh: the mesh is read as LIRE_MAILLAGE(FORMAT="MED",
!> UNITE=U) reads it, from the file of unit U that run_aster names fort.U, and the tuple
!> (mesh, fields) is returned with the fields' dict empty (parasol reads no field of a MED
!> file; the .mess says so). The balancers (cellBalancer, nodeBalancer) and outMesh are MPI
!> objects parasol does not have: asking for them is a located error; nodeGrpToGather,
!> deterministic and sequenceToOrder change nothing on one process.
submodule(deck_interpreter) deck_interp_medutils
    implicit none

    character(len=*), parameter :: SPLIT = 'splitMeshAndFieldsFromMedFile'
    character(len=*), parameter :: SPLIT_PARAMETERS(*) = [character(len=16) :: 'filename', &
        'cellBalancer', 'nodeBalancer', 'outMesh', 'nodeGrpToGather', 'deterministic', &
        'sequenceToOrder']

contains

    module procedure split_med_file
        type(value_t) :: vals(size(SPLIT_PARAMETERS)), mesh, fields
        logical :: given(size(SPLIT_PARAMETERS))
        type(value_list_t) :: kw
        type(value_list_t) :: read_kw
        integer :: k, j, n, unit, ios
        character(len=:), allocatable :: name
        given = .false.
        if (size(args) > size(SPLIT_PARAMETERS)) then
            call fail(st, ctx, id, SPLIT // '() takes at most ' // &
                to_text(size(SPLIT_PARAMETERS)) // ' arguments, got ' // to_text(size(args)))
            return
        end if
        do k = 1, size(args)
            vals(k) = args(k); given(k) = .true.
        end do
        if (nitems(kwargs) > 0) then
            kw = unpack_value(kwargs)
            do k = 1, size(kw%keys)
                j = 0
                do n = 1, size(SPLIT_PARAMETERS)
                    if (trim(SPLIT_PARAMETERS(n)) == kw%keys(k)%s) j = n
                end do
                if (j == 0) then
                    call fail(st, ctx, id, SPLIT // '() got an unexpected keyword argument ' // &
                        kw%keys(k)%s // ' (its parameters: filename, cellBalancer, ' // &
                        'nodeBalancer, outMesh, nodeGrpToGather, deterministic, ' // &
                        'sequenceToOrder)'); return
                end if
                if (given(j)) then
                    call fail(st, ctx, id, SPLIT // '() got several values for argument ' // &
                              kw%keys(k)%s); return
                end if
                vals(j) = kw%items(k); given(j) = .true.
            end do
        end if
        if (.not. given(1)) then
            call fail(st, ctx, id, SPLIT // '() is missing its argument filename'); return
        end if
        if (.not. want_text(ctx, id, vals(1), SPLIT // '(filename)', st)) return
        do k = 2, 3
            if (given(k)) then
                if (is_true(ctx, vals(k))) then
                    call fail(st, ctx, id, SPLIT // '(' // trim(SPLIT_PARAMETERS(k)) // &
                        '=True): the balancers are MPI objects of a parallel run; parasol ' // &
                        'runs as one process and has none (leave it False)'); return
                end if
            end if
        end do
        if (given(4)) then
            if (vals(4)%kind /= VK_NONE) then
                call fail(st, ctx, id, SPLIT // '(outMesh=...): a ParallelMesh to fill is ' // &
                          'an MPI object parasol does not have (leave it None)'); return
            end if
        end if
        ! the file: run_aster names the file of logical unit U fort.U in the work folder
        name = vals(1)%s
        unit = -1
        if (len(name) > 5) then
            if (name(1:5) == 'fort.' .and. verify(name(6:), '0123456789') == 0 .and. &
                len(name) <= 14) read (name(6:), *, iostat=ios) unit
        end if
        if (unit <= 0) then
            call fail(st, ctx, id, SPLIT // '("' // name // '"): parasol reads a MED file ' // &
                'through its logical unit, named fort.U as run_aster names it (bind the ' // &
                'file to unit U by an F line of the export file, --unit U=FILE or ' // &
                'DEFI_FICHIER, and give "fort.U")'); return
        end if
        allocate (read_kw%items(2), read_kw%keys(2), read_kw%key_line(2), read_kw%key_col(2))
        read_kw%items(1) = str_value('MED')
        read_kw%keys(1)%s = 'FORMAT'
        read_kw%items(2) = int_value(int(unit, i8))
        read_kw%keys(2)%s = 'UNITE'
        read_kw%key_line = int(ctx%ast%nodes(id)%line)
        read_kw%key_col = int(ctx%ast%nodes(id)%col)
        call run_catalog_command(ctx, id, 'LIRE_MAILLAGE', pack_values(VK_FACTOR, read_kw), &
                                 mesh, st)
        if (st%failed()) return
        if (.not. ctx%checking) call ctx%write_mess('  -- ' // SPLIT // '("' // name // &
            '"): one process, whose part is the whole mesh; the fields of the MED file ' // &
            'are not read (the dict of fields is empty)')
        fields = ctx%heap%new_dict()
        v = sequence_value(VK_TUPLE, values_of(mesh, fields))
    end procedure split_med_file

end submodule deck_interp_medutils
